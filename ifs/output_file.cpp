// SPDX-License-Identifier: Apache-2.0
#include "ifs/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx {
namespace fs = std::filesystem;

namespace {

// The system's reason for errno value `code` ("No such file or directory").
std::string reason(int code) {
  return std::generic_category().message(code);
}

Error cannot_write(const fs::path& target, const std::string& why) {
  return Error(ErrorKind::io, fmt::format("{}: cannot write: {}", target.string(), why));
}

// The file a write to `target` replaces: the target itself, or the file it points to when it is a
// symbolic link to an existing file (written through, as cp does). A dangling link is replaced.
fs::path destination_of(const fs::path& target) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(target, ec)) && fs::exists(target, ec)) {
    fs::path resolved = fs::canonical(target, ec);
    if (!ec) return resolved;
  }
  return target;
}

fs::path folder_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// A name beside `destination` for its temporary file: hidden, and telling whose it is.
fs::path temporary_name(const fs::path& destination, std::uint32_t salt) {
  std::string stem = destination.filename().string();
  if (stem.size() > 96) stem.resize(96);  // room for the rest within NAME_MAX
  return folder_of(destination) / fmt::format(".{}.{:08x}.ifsfx-tmp", stem, salt);
}

}  // namespace

void InputFiles::add(const fs::path& path) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) return;
  files_.push_back(
      {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino), path});
}

const fs::path* InputFiles::find(const fs::path& path) const {
  struct stat st {};
  if (files_.empty() || path.empty() || ::stat(path.c_str(), &st) != 0) return nullptr;
  for (const Entry& e : files_)
    if (e.device == static_cast<std::uint64_t>(st.st_dev) &&
        e.inode == static_cast<std::uint64_t>(st.st_ino))
      return &e.path;
  return nullptr;
}

void check_output(const fs::path& target, const OutputOptions& options) {
  if (target.empty()) throw Error(ErrorKind::invalid_argument, "output: no file name given");
  if (const fs::path* input = options.inputs.find(target))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: is the same file as the input {} (an output never replaces an "
                            "input; write it elsewhere)",
                            target.string(), input->string()));
  const fs::path destination = destination_of(target);
  std::error_code ec;
  if (fs::is_directory(destination, ec)) throw cannot_write(target, "it is a folder");
  const fs::path folder = folder_of(destination);
  if (!fs::is_directory(folder, ec))
    throw cannot_write(target, fmt::format("folder '{}' does not exist", folder.string()));
  if (::access(folder.c_str(), W_OK) != 0)
    throw cannot_write(
        target, fmt::format("folder '{}' is not writable ({})", folder.string(), reason(errno)));
}

bool same_output(const fs::path& a, const fs::path& b) {
  InputFiles first;
  first.add(a);
  if (first.find(b) != nullptr) return true;
  std::error_code ea, eb;
  const fs::path na = fs::weakly_canonical(fs::absolute(a), ea);
  const fs::path nb = fs::weakly_canonical(fs::absolute(b), eb);
  return !ea && !eb && na == nb;
}

OutputFile::OutputFile(fs::path target, const OutputOptions& options)
    : target_(std::move(target)), cancel_(options.cancel) {
  check_output(target_, options);
  destination_ = destination_of(target_);
  // O_EXCL on a random name: the file is new and ours; 0666 so that the umask applies, as for any
  // file the user creates.
  std::random_device entropy;
  for (int attempt = 0; attempt < 64; ++attempt) {
    fs::path candidate = temporary_name(destination_, entropy());
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      temporary_ = std::move(candidate);
      return;
    }
    if (errno != EEXIST) throw cannot_write(target_, reason(errno));
  }
  throw cannot_write(target_, "no free temporary name in its folder");
}

OutputFile::~OutputFile() {
  discard();
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : target_(std::move(other.target_)),
      destination_(std::move(other.destination_)),
      temporary_(std::exchange(other.temporary_, {})),
      cancel_(other.cancel_) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    discard();
    target_ = std::move(other.target_);
    destination_ = std::move(other.destination_);
    temporary_ = std::exchange(other.temporary_, {});
    cancel_ = other.cancel_;
  }
  return *this;
}

void OutputFile::commit() {
  commit_together(std::span<OutputFile>(this, 1));
}

void commit_together(std::span<OutputFile> files) {
  for (const OutputFile& file : files)
    if (file.temporary_.empty())
      throw Error(ErrorKind::io,
                  fmt::format("{}: already committed or discarded", file.target_.string()));
  for (OutputFile& file : files) {
    if (!file.cancel_.requested()) continue;
    for (OutputFile& each : files) each.discard();
    file.cancel_.check(file.target_.c_str());
  }
  std::size_t done = 0;
  try {
    for (; done < files.size(); ++done) files[done].rename_into_place();
  } catch (...) {
    for (std::size_t rest = done + 1; rest < files.size(); ++rest) files[rest].discard();
    throw;
  }
}

void OutputFile::rename_into_place() {
  if (std::rename(temporary_.c_str(), destination_.c_str()) != 0) {
    const int code = errno;
    discard();
    throw cannot_write(target_, code == EISDIR
                                    ? std::string("it is a folder")
                                    : fmt::format("cannot rename into place ({})", reason(code)));
  }
  temporary_.clear();
}

fs::path OutputFile::keep_partial() noexcept {
  if (temporary_.empty()) return {};
  try {
    const fs::path folder = destination_.parent_path();  // empty: the current folder
    const std::string stem = destination_.stem().string(), ext = destination_.extension().string();
    for (int n = 1; n <= 1000; ++n) {
      const fs::path name = folder / (n == 1 ? fmt::format("{}.partial{}", stem, ext)
                                             : fmt::format("{}.partial-{}{}", stem, n, ext));
      // Never over an existing file: renameat2 refuses to replace; where the file system cannot
      // say so, a hard link (which fails on an existing name) and an unlink do the same.
      int r = ::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, name.c_str(), RENAME_NOREPLACE);
      if (r != 0 && (errno == EINVAL || errno == ENOSYS)) {
        r = ::link(temporary_.c_str(), name.c_str());
        if (r == 0) ::unlink(temporary_.c_str());
      }
      if (r == 0) {
        temporary_.clear();
        return name;
      }
      if (errno != EEXIST) break;
    }
  } catch (...) {
  }
  discard();
  return {};
}

void OutputFile::discard() noexcept {
  if (temporary_.empty()) return;
  ::unlink(temporary_.c_str());
  temporary_.clear();
}

void write_file(const fs::path& target, std::string_view bytes, const OutputOptions& options) {
  OutputFile out(target, options);
  write_file(out, bytes);
  out.commit();
}

void write_file(OutputFile& out, std::string_view bytes) {
  const fs::path& target = out.target();
  std::FILE* file = std::fopen(out.temporary().c_str(), "wb");
  if (file == nullptr) throw cannot_write(target, reason(errno));
  const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), file);
  // A short write without an errno (there always is one on Linux) is reported as EIO, never as
  // "Success".
  const int write_error = written != bytes.size() ? (errno != 0 ? errno : EIO) : 0;
  const int close_error = std::fclose(file) != 0 ? (errno != 0 ? errno : EIO) : 0;
  if (write_error != 0 || close_error != 0)
    throw cannot_write(target, reason(write_error != 0 ? write_error : close_error));
}

}  // namespace ifsfx
