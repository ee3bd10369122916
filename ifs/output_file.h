// SPDX-License-Identifier: Apache-2.0
// The one output policy (docs/design.md §8). Every file ifsfx writes — images, steal maps, presets,
// movies, image sequences, recordings — goes through an OutputFile:
//   - an output that is the same file as an input (same device and inode: through symbolic and
//     hard links, whatever the spelling of the path) is refused before anything is written;
//   - the bytes go to a fresh temporary file beside the target, reserved with O_EXCL under a
//     random name, so no other file (an unrelated OUT.part) is ever touched;
//   - the target is replaced by one rename, and only on success: after a failure or a stop request
//     an existing target keeps its contents, and the temporary file is removed;
//   - where a partial result is still useful (a playable movie of the frames done), it is kept
//     under a separate name, STEM.partial.EXT, that never replaces an existing file.
// A target that is a symbolic link to a file is written through (the file it points to gets the
// new contents and the link stays), as cp does.
//
//   OutputFile out("fern.png", {.inputs = inputs, .cancel = stop});
//   encode_to(out.temporary());
//   out.commit();  // or leave the scope: the temporary is removed, the target untouched
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "ifs/cancel.h"

namespace ifsfx {

// The files a command reads, known by device and inode.
class InputFiles {
 public:
  // Adds the file `path` names when one exists (a symbolic link counts as the file it points to);
  // a name that is no file (a shipped preset's name, a pattern, a folder) is ignored.
  void add(const std::filesystem::path& path);
  // The input that `path` is the same file as, or nullptr (also when `path` does not exist).
  const std::filesystem::path* find(const std::filesystem::path& path) const;
  bool empty() const { return files_.empty(); }

 private:
  struct Entry {
    std::uint64_t device = 0, inode = 0;
    std::filesystem::path path;  // as the command line named it, for messages
  };
  std::vector<Entry> files_;
};

struct OutputOptions {
  InputFiles inputs;   // the command's inputs: refused as this output (Error{invalid_argument})
  CancelToken cancel;  // polled by commit(): a stop requested before it leaves the target as it was
};

// Throws what constructing an OutputFile for `target` would throw, without creating anything: for
// the checks before long work. Error{invalid_argument} when the target is one of the inputs or no
// name is given; Error{io} "TARGET: cannot write: ..." when its folder is missing or not
// writable, or when the target is a folder.
void check_output(const std::filesystem::path& target, const OutputOptions& options = {});

// Whether two output names denote the same file (the same existing file, or the same path once
// made absolute and normalised): two outputs of one command must differ.
bool same_output(const std::filesystem::path& a, const std::filesystem::path& b);

class OutputFile {
 public:
  // Checks `target` (check_output) and reserves its temporary file. Throws as check_output does,
  // and Error{io} with the system's reason when the temporary cannot be created.
  explicit OutputFile(std::filesystem::path target, const OutputOptions& options = {});
  ~OutputFile();  // removes the temporary file unless it was committed or kept
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // The name given, and the file that will be replaced (the name with symbolic links followed).
  const std::filesystem::path& target() const { return target_; }
  // Where to write: an empty file created for this output, in the target's folder.
  const std::filesystem::path& temporary() const { return temporary_; }

  // Renames the temporary file over the target. Throws Error{interrupted} (the temporary removed,
  // the target untouched) when a stop was requested, and Error{io} with the system's reason when
  // the rename fails.
  void commit();
  // Keeps what was written as STEM.partial.EXT beside the target (STEM.partial-2.EXT, ... when
  // taken): never replaces a file. Returns that name, or an empty path when it could not be kept
  // (the temporary is then removed).
  std::filesystem::path keep_partial() noexcept;
  // Removes the temporary file now.
  void discard() noexcept;

  friend void commit_together(std::span<OutputFile> files);

 private:
  void rename_into_place();  // commit() without the stop poll

  std::filesystem::path target_, destination_, temporary_;
  CancelToken cancel_;
};

// Commits several outputs of one command (an image and its steal map, the frames of a sequence)
// so that a stop leaves them all new or all as they were: the stop request is polled once, before
// the first rename (commit() polls it per file, and a stop between two renames would leave some
// targets new and the rest old). Throws Error{interrupted} with every temporary removed and every
// target untouched when a stop was requested, and Error{io} as commit() does when a rename fails
// (a folder that appeared in the way): the outputs before it are in place, the rest removed.
void commit_together(std::span<OutputFile> files);

// `bytes` written to `target` under the policy (a preset, a report).
void write_file(const std::filesystem::path& target, std::string_view bytes,
                const OutputOptions& options = {});
// `bytes` written into the temporary file of `out`, not committed (see commit_together).
void write_file(OutputFile& out, std::string_view bytes);

}  // namespace ifsfx
