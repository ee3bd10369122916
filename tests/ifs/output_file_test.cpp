// SPDX-License-Identifier: Apache-2.0
// The output policy (docs/design.md §8): inputs are never outputs, temporaries are fresh and
// exclusive, the target is replaced only on success, partial results never replace a file.
#include "ifs/output_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/steal_map.h"

namespace ifsfx {
namespace {

namespace fs = std::filesystem;

class output_file : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ifsfx-output-file-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The names in the folder.
  std::set<std::string> names() const {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.insert(e.path().filename().string());
    return out;
  }

  fs::path dir_;
};

void put(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The Error thrown by `f`, or a test failure.
template <class F>
Error error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error(ErrorKind::parse, "");
}

TEST_F(output_file, target_is_replaced_only_by_commit) {
  put(dir_ / "out.txt", "good");
  {
    OutputFile out(dir_ / "out.txt");
    put(out.temporary(), "new");
    EXPECT_EQ(contents(dir_ / "out.txt"), "good");
    out.commit();
  }
  EXPECT_EQ(contents(dir_ / "out.txt"), "new");
  EXPECT_EQ(names(), (std::set<std::string>{"out.txt"}));
}

TEST_F(output_file, abandoned_output_leaves_the_target_and_no_temporary) {
  put(dir_ / "out.txt", "good");
  {
    OutputFile out(dir_ / "out.txt");
    put(out.temporary(), "half");
  }
  EXPECT_EQ(contents(dir_ / "out.txt"), "good");
  EXPECT_EQ(names(), (std::set<std::string>{"out.txt"}));
}

TEST_F(output_file, temporaries_are_fresh_files_and_never_a_fixed_part_name) {
  put(dir_ / "out.png.part", "unrelated");
  put(dir_ / "map.part", "unrelated too");
  OutputFile a(dir_ / "out.png"), b(dir_ / "out.png");
  EXPECT_NE(a.temporary(), b.temporary());
  EXPECT_EQ(a.temporary().parent_path(), dir_);
  EXPECT_TRUE(fs::is_regular_file(a.temporary()));
  EXPECT_EQ(fs::file_size(a.temporary()), 0u);
  a.discard();
  b.discard();
  // The writers of the library go through it too: an unrelated OUT.part or MAP.part survives.
  write_image(dir_ / "out.png", cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(9)));
  StealMap map{cv::Mat(2, 2, CV_32FC2, cv::Scalar::all(0.5)), cv::Mat(2, 2, CV_8UC1, 255)};
  save(map, dir_ / "map");
  EXPECT_EQ(contents(dir_ / "out.png.part"), "unrelated");
  EXPECT_EQ(contents(dir_ / "map.part"), "unrelated too");
  EXPECT_EQ(names(), (std::set<std::string>{"out.png", "out.png.part", "map", "map.part"}));
}

TEST_F(output_file, an_input_is_refused_under_any_name) {
  put(dir_ / "in.png", "photo");
  fs::create_hard_link(dir_ / "in.png", dir_ / "hard.png");
  fs::create_symlink(dir_ / "in.png", dir_ / "soft.png");
  OutputOptions options;
  options.inputs.add(dir_ / "in.png");
  options.inputs.add("no-such-file.png");  // ignored
  options.inputs.add("barnsley-fern");     // a shipped preset's name: ignored
  for (const fs::path& name : {dir_ / "in.png", dir_ / "hard.png", dir_ / "soft.png",
                               dir_ / "." / "in.png", dir_ / ".." / dir_.filename() / "in.png"}) {
    const Error e = error_of([&] { OutputFile out(name, options); });
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument) << name;
    EXPECT_EQ(std::string(e.what()),
              name.string() + ": is the same file as the input " + (dir_ / "in.png").string() +
                  " (an output never replaces an input; write it elsewhere)");
  }
  EXPECT_EQ(contents(dir_ / "in.png"), "photo");
  EXPECT_EQ(names(), (std::set<std::string>{"in.png", "hard.png", "soft.png"}));
  EXPECT_NO_THROW(OutputFile(dir_ / "other.png", options));
}

TEST_F(output_file, a_folder_in_the_way_is_named_with_the_real_reason) {
  fs::create_directory(dir_ / "out.png");
  const Error e = error_of([&] { write_image(dir_ / "out.png", cv::Mat(4, 4, CV_8UC1)); });
  EXPECT_EQ(e.kind(), ErrorKind::io);
  EXPECT_EQ(std::string(e.what()), (dir_ / "out.png").string() + ": cannot write: it is a folder");
  // A folder that appears after the checks: the rename's own errno, never "Success".
  OutputFile out(dir_ / "late.txt");
  fs::create_directory(dir_ / "late.txt");
  put(dir_ / "late.txt" / "inside", "x");
  const Error late = error_of([&] { out.commit(); });
  EXPECT_EQ(late.kind(), ErrorKind::io);
  EXPECT_EQ(std::string(late.what()).find("Success"), std::string::npos) << late.what();
  EXPECT_NE(std::string(late.what()).find("late.txt: cannot write: "), std::string::npos)
      << late.what();
  EXPECT_EQ(names(), (std::set<std::string>{"out.png", "late.txt"}));
}

TEST_F(output_file, missing_folder_is_named_before_anything_is_written) {
  const Error e = error_of([&] { OutputFile out(dir_ / "missing" / "out.txt"); });
  EXPECT_EQ(e.kind(), ErrorKind::io);
  EXPECT_EQ(std::string(e.what()), (dir_ / "missing" / "out.txt").string() +
                                       ": cannot write: folder '" + (dir_ / "missing").string() +
                                       "' does not exist");
}

TEST_F(output_file, a_stop_request_before_commit_leaves_the_target) {
  put(dir_ / "out.txt", "good");
  std::atomic<bool> stop{false};
  OutputFile out(dir_ / "out.txt", {.cancel = CancelToken(&stop)});
  put(out.temporary(), "new");
  stop = true;
  const Error e = error_of([&] { out.commit(); });
  EXPECT_EQ(e.kind(), ErrorKind::interrupted);
  EXPECT_EQ(contents(dir_ / "out.txt"), "good");
  EXPECT_EQ(names(), (std::set<std::string>{"out.txt"}));
}

TEST_F(output_file, outputs_committed_together_are_all_new_or_all_as_they_were) {
  std::atomic<bool> stop{false};
  const auto stage = [&](const std::string& text) {
    std::vector<OutputFile> files;
    for (const char* name : {"a.txt", "b.txt", "c.txt"}) {
      files.emplace_back(dir_ / name, OutputOptions{.cancel = CancelToken(&stop)});
      put(files.back().temporary(), text);
    }
    return files;
  };
  std::vector<OutputFile> first = stage("one");
  commit_together(first);
  for (const char* name : {"a.txt", "b.txt", "c.txt"}) EXPECT_EQ(contents(dir_ / name), "one");

  // A stop before the commit: no target replaced, no temporary left.
  std::vector<OutputFile> stopped = stage("two");
  stop = true;
  EXPECT_EQ(error_of([&] { commit_together(stopped); }).kind(), ErrorKind::interrupted);
  for (const char* name : {"a.txt", "b.txt", "c.txt"}) EXPECT_EQ(contents(dir_ / name), "one");
  EXPECT_EQ(names(), (std::set<std::string>{"a.txt", "b.txt", "c.txt"}));
  stop = false;

  // A rename that fails (a folder put in the way of b after the checks): a is in place, b and c
  // keep their contents, and no temporary is left.
  std::vector<OutputFile> blocked = stage("three");
  fs::remove(dir_ / "b.txt");
  fs::create_directory(dir_ / "b.txt");
  put(dir_ / "b.txt" / "inside", "x");
  const Error e = error_of([&] { commit_together(blocked); });
  EXPECT_EQ(e.kind(), ErrorKind::io);
  EXPECT_NE(std::string(e.what()).find("b.txt: cannot write: "), std::string::npos) << e.what();
  EXPECT_EQ(contents(dir_ / "a.txt"), "three");
  EXPECT_EQ(contents(dir_ / "c.txt"), "one");
  EXPECT_EQ(names(), (std::set<std::string>{"a.txt", "b.txt", "c.txt"}));
  // Committed or discarded files cannot be committed again.
  EXPECT_EQ(error_of([&] { commit_together(blocked); }).kind(), ErrorKind::io);
}

TEST_F(output_file, partial_result_is_kept_beside_and_never_over_a_file) {
  put(dir_ / "movie.mkv", "good movie");
  put(dir_ / "movie.partial.mkv", "an earlier partial");
  OutputFile out(dir_ / "movie.mkv");
  put(out.temporary(), "frames done");
  EXPECT_EQ(out.keep_partial(), dir_ / "movie.partial-2.mkv");
  EXPECT_EQ(contents(dir_ / "movie.mkv"), "good movie");
  EXPECT_EQ(contents(dir_ / "movie.partial.mkv"), "an earlier partial");
  EXPECT_EQ(contents(dir_ / "movie.partial-2.mkv"), "frames done");
  EXPECT_EQ(names(),
            (std::set<std::string>{"movie.mkv", "movie.partial.mkv", "movie.partial-2.mkv"}));
}

TEST_F(output_file, a_symbolic_link_target_is_written_through) {
  fs::create_directory(dir_ / "real");
  put(dir_ / "real" / "file.txt", "old");
  fs::create_symlink(dir_ / "real" / "file.txt", dir_ / "link.txt");
  write_file(dir_ / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  EXPECT_EQ(contents(dir_ / "real" / "file.txt"), "new");
  EXPECT_EQ(names(), (std::set<std::string>{"real", "link.txt"}));
}

TEST_F(output_file, two_names_of_one_file_are_the_same_output) {
  EXPECT_TRUE(same_output(dir_ / "a.png", dir_ / "." / "a.png"));
  EXPECT_FALSE(same_output(dir_ / "a.png", dir_ / "b.png"));
  put(dir_ / "a.png", "x");
  fs::create_hard_link(dir_ / "a.png", dir_ / "b.png");
  EXPECT_TRUE(same_output(dir_ / "a.png", dir_ / "b.png"));
}

}  // namespace
}  // namespace ifsfx
