// SPDX-License-Identifier: Apache-2.0
// Fractint's .ifs format: named entries `NAME { a b c d e f p ... }`, `;` comments to the end of
// the line, numbers separated by spaces, tabs, commas or newlines. Fractint's a b c d e f are
// ours: x' = a x + b y + e, y' = c x + d y + f (docs/design.md §1); its p are weights, drawn from
// by Fractint's selection rule (fractint_probabilities).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "ifs/fractint.h"

#include "ifs/error.h"

namespace ifsfx {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}
bool is_separator(char c) {
  return is_space(c) || c == ',';
}
bool ends_token(char c) {
  return is_separator(c) || c == ';' || c == '{' || c == '}';
}

// A number token; from_chars does not take a leading '+', Fractint files sometimes have one.
bool parse_number(std::string_view token, double& x) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
  return ec == std::errc() && end == token.data() + token.size();
}

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

struct Number {
  double value;
  int line;
};

class FractintReader {
 public:
  FractintReader(std::string_view text, const std::string& filename)
      : text_(text), filename_(filename) {}

  std::vector<detail::FractintEntry> entries() {
    std::vector<detail::FractintEntry> out;
    while (true) {
      skip(is_space);
      if (at_end()) break;
      out.push_back(entry());
    }
    return out;
  }

 private:
  Error error_at(ErrorKind kind, int line, const std::string& what) const {
    return Error(kind, fmt::format("{}:{}: {}", filename_, line, what));
  }
  [[noreturn]] void fail(ErrorKind kind, int line, const std::string& what) const {
    throw error_at(kind, line, what);
  }

  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }

  // Skips characters for which `skippable` holds, and `;` comments; returns the first comment's
  // text met on the current line (an entry's description sits there, after its brace).
  template <class Pred>
  std::string skip(Pred skippable) {
    std::string comment;
    const int start_line = line_;
    while (!at_end()) {
      const char c = peek();
      if (c == ';') {
        const std::size_t begin = ++pos_;
        while (!at_end() && peek() != '\n') ++pos_;
        if (comment.empty() && line_ == start_line)
          comment = trim(text_.substr(begin, pos_ - begin));
      } else if (skippable(c)) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        break;
      }
    }
    return comment;
  }

  static std::string trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return std::string(s);
  }

  // A name ends at its tag's '(' too; a number token does not, so "(3D)" inside braces is
  // reported as not a number.
  std::string_view token(bool is_name) {
    const std::size_t begin = pos_;
    while (!at_end() && !ends_token(peek()) && !(is_name && peek() == '(')) ++pos_;
    return text_.substr(begin, pos_ - begin);
  }

  // Fractint reads no number on the line of an entry's opening brace (it looks there only for
  // "(3D)"), so artists write notes after the brace without a ';' ("sq475a {Tony Hanmer
  // 23/1/2004, Designed with BRAZIL"). Such a line -- its first word not a number, and not the
  // whole entry -- is the entry's description, and the numbers start on the next line. A line
  // that starts with a number is read as numbers (entries written on one line, or starting on
  // the brace line), so that a typo there is still reported, not taken for a note.
  std::optional<std::string> brace_line_note() {
    const std::size_t eol = std::min(text_.find('\n', pos_), text_.size());
    const std::string_view rest = text_.substr(pos_, eol - pos_);
    if (rest.find_first_of("{}") != std::string_view::npos) return std::nullopt;
    const std::string_view before_comment = rest.substr(0, rest.find(';'));
    std::size_t i = 0;
    while (i < before_comment.size() && is_separator(before_comment[i])) ++i;
    std::size_t j = i;
    while (j < before_comment.size() && !is_separator(before_comment[j])) ++j;
    double x = 0;
    if (j == i || parse_number(before_comment.substr(i, j - i), x)) return std::nullopt;
    pos_ = eol;
    std::string note = trim(before_comment);
    if (const auto semicolon = rest.find(';'); note.empty() && semicolon != std::string_view::npos)
      note = trim(rest.substr(semicolon + 1));
    return note;
  }

  // Keeps the first error found inside an entry (the entry's own; the file reads on).
  static void defer(detail::FractintEntry& entry, Error error) {
    if (!entry.error) entry.error = std::move(error);
  }

  // Errors of the file's structure (a missing brace) throw at once; errors inside a well-formed
  // entry (a (3D) tag, a bad number, a count that does not fit) stay with that entry, so that
  // the other entries of the file can still be used.
  detail::FractintEntry entry() {
    const std::size_t begin = pos_;
    if (peek() == '{' || peek() == '}' || peek() == '(' || peek() == ',')
      fail(ErrorKind::parse, line_,
           fmt::format("an entry starts with its name, as in NAME {{ a b c d e f p ... }} "
                       "(got '{}')",
                       peek()));
    detail::FractintEntry out;
    out.line = line_;
    out.name = std::string(token(true));
    const std::string& name = out.name;
    skip(is_space);
    if (!at_end() && peek() == '(') read_tag(out);
    skip(is_space);
    const int brace_line = open_brace(name);

    IfsPreset preset;
    if (std::optional<std::string> note = brace_line_note())
      preset.description = std::move(*note);
    else
      preset.description = skip(is_separator);
    const std::vector<Number> numbers = read_numbers(out, brace_line);
    ++pos_;  // the closing brace

    if (out.error) return out;
    try {
      preset.ifs = to_ifs(name, out.line, numbers);
    } catch (const Error& e) {
      out.error = e;
      return out;
    }
    preset.ifs.name = name;
    preset.origin = fmt::format("{}:{}", filename_, name);
    preset.format = PresetFormat::fractint;
    preset.text = std::string(text_.substr(begin, pos_ - begin)) + "\n";
    out.preset = std::move(preset);
    return out;
  }

  // The tag after an entry's name, "(3D)" or another: either makes the entry unusable.
  void read_tag(detail::FractintEntry& entry) {
    const std::size_t tag_begin = pos_;
    while (!at_end() && peek() != ')' && peek() != '\n') ++pos_;
    if (at_end() || peek() != ')')
      fail(ErrorKind::parse, line_,
           fmt::format("entry '{}': missing ')' after its tag", entry.name));
    const std::string tag = lowercase(trim(text_.substr(tag_begin + 1, pos_ - tag_begin - 1)));
    ++pos_;
    if (tag == "3d")
      defer(entry, error_at(ErrorKind::unsupported, entry.line,
                            fmt::format("entry '{}': only 2-D IFSs are supported (got a (3D) "
                                        "entry)",
                                        entry.name)));
    else
      defer(entry, error_at(ErrorKind::parse, entry.line,
                            fmt::format("entry '{}': unknown tag, Fractint knows only (3D) (got "
                                        "'{}')",
                                        entry.name, text_.substr(tag_begin, pos_ - tag_begin))));
  }

  // The '{' after the name (and tag), passed; returns its line.
  int open_brace(const std::string& name) {
    if (at_end() || peek() != '{') {
      std::string got = "the end of the file";
      if (!at_end()) {
        const std::string_view next = token(false);
        got = fmt::format("'{}'", next.empty() ? std::string_view(&text_[pos_], 1) : next);
      }
      fail(ErrorKind::parse, line_,
           fmt::format("entry '{}': expected '{{' after the name (got {})", name, got));
    }
    const int brace_line = line_;
    ++pos_;
    return brace_line;
  }

  // The numbers up to the entry's closing '}' (left unread); a token that is not a number is the
  // entry's error, unless it starts the next entry (then the '}' is missing).
  std::vector<Number> read_numbers(detail::FractintEntry& entry, int brace_line) {
    const std::string& name = entry.name;
    std::vector<Number> numbers;
    while (true) {
      skip(is_separator);
      if (at_end())
        fail(ErrorKind::parse, brace_line,
             fmt::format("entry '{}': missing '}}' (got the end of the file)", name));
      if (peek() == '}') break;
      if (peek() == '{')
        fail(ErrorKind::parse, line_,
             fmt::format("entry '{}': missing '}}' before the next '{{'", name));
      const int line = line_;
      const std::string_view t = token(false);
      double x = 0;
      if (!parse_number(t, x)) {
        skip(is_space);
        if (!at_end() && (peek() == '{' || peek() == '('))  // the next entry's name
          fail(ErrorKind::parse, line,
               fmt::format("entry '{}': missing '}}' before the next entry '{}'", name, t));
        defer(entry, error_at(ErrorKind::parse, line,
                              fmt::format("entry '{}': not a number (got '{}')", name, t)));
      }
      numbers.push_back({x, line});
    }
    return numbers;
  }

  // 7 numbers per map (a b c d e f p), or 6 (a b c d e f) with default probabilities. A count that
  // is a multiple of both (42, 84, ...) is read with p unless those p are not probabilities.
  Ifs to_ifs(const std::string& name, int name_line, const std::vector<Number>& numbers) const {
    const std::size_t n = numbers.size();
    if (n == 0)
      fail(ErrorKind::invalid_ifs, name_line,
           fmt::format("entry '{}': an IFS needs at least one map (got 0 numbers)", name));
    auto probabilities_look_right = [&] {
      double sum = 0;
      for (std::size_t i = 6; i < n; i += 7) {
        if (!(numbers[i].value >= 0 && numbers[i].value <= 1)) return false;
        sum += numbers[i].value;
      }
      return std::abs(sum - 1) < 0.02;
    };
    std::size_t stride = 0;
    if (n % 7 == 0 && (n % 6 != 0 || probabilities_look_right()))
      stride = 7;
    else if (n % 6 == 0)
      stride = 6;
    else
      fail(ErrorKind::parse, name_line,
           fmt::format("entry '{}': needs 7 numbers per map (a b c d e f p) or 6 (a b c d e f) "
                       "(got {}, a multiple of neither)",
                       name, n));

    Ifs ifs;
    for (std::size_t i = 0; i < n; i += stride) {
      const std::size_t map = i / stride + 1;
      std::array<double, 6> k{};
      for (std::size_t j = 0; j < 6; ++j) {
        k[j] = numbers[i + j].value;
        if (!std::isfinite(k[j]))
          fail(ErrorKind::invalid_ifs, numbers[i + j].line,
               fmt::format("entry '{}': map {}: coefficients must be finite numbers (got {})", name,
                           map, k[j]));
      }
      ifs.maps.push_back(AffineMap::from_coefficients(k));
      if (stride == 7) {
        const Number& p = numbers[i + 6];
        if (!std::isfinite(p.value))
          fail(ErrorKind::invalid_ifs, p.line,
               fmt::format("entry '{}': map {}: probability must be a finite number (got {})", name,
                           map, p.value));
        ifs.probabilities.push_back(p.value);
      }
    }
    if (stride == 7 && std::all_of(ifs.probabilities.begin(), ifs.probabilities.end(),
                                   [](double p) { return p == 0; }))
      fail(ErrorKind::invalid_ifs, name_line,
           fmt::format("entry '{}': probabilities: they must not all be zero (got sum 0)", name));
    if (stride == 7) ifs.probabilities = fractint_probabilities(ifs.probabilities);
    return ifs;
  }

  std::string_view text_;
  const std::string& filename_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

std::vector<double> fractint_probabilities(const std::vector<double>& weights) {
  // Weights that already are probabilities are kept as they are: Fractint's walk gives exactly
  // them (up to the rounding of the running sums, which is not worth carrying over).
  double sum = 0;
  bool negative = false;
  for (double w : weights) sum += w, negative = negative || w < 0;
  if (!negative && std::abs(sum - 1) <= 1e-9) return weights;
  // Map k is drawn for r ∈ (L_{k−1}, L_k], L_k = the running maximum of the cumulative sums
  // S_0..S_k clamped to [0, 1] (L_{−1} = 0); the last map takes r ∈ (L_{N−2}, 1]. A negative
  // weight lowers S, so the maps after it get nothing until S climbs back over L.
  std::vector<double> p(weights.size(), 0.0);
  double cumulative = 0, reached = 0;
  for (std::size_t k = 0; k + 1 < weights.size(); ++k) {
    cumulative += weights[k];
    const double next = std::max(reached, std::clamp(cumulative, 0.0, 1.0));
    p[k] = next - reached;
    reached = next;
  }
  if (!p.empty()) p.back() = 1 - reached;
  return p;
}

namespace detail {

std::vector<FractintEntry> read_fractint_entries(std::string_view text,
                                                 const std::string& filename) {
  return FractintReader(text, filename).entries();
}

}  // namespace detail

std::vector<IfsPreset> parse_fractint(std::string_view text, const std::string& filename) {
  std::vector<IfsPreset> presets;
  for (auto& entry : detail::read_fractint_entries(text, filename)) {
    if (entry.error) throw *entry.error;
    presets.push_back(std::move(*entry.preset));
  }
  return presets;
}

}  // namespace ifsfx
