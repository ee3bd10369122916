// SPDX-License-Identifier: Apache-2.0
// The studio's confinement to --folder (studio/folder.h): only plain names, no `..`, no absolute
// path, no hidden file, no link that leads out; and --source found in the current folder or in
// --folder (studio/server.h).
#include "studio/folder.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "studio/server.h"

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;

class studio_folder : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("ifsfx-studio-folder-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "folder" / "sub");
    root_ = fs::canonical(root_);
    folder_ = root_ / "folder";
    put(folder_ / "photo.png");
    put(folder_ / "clip.MP4");
    put(folder_ / ".hidden.png");
    put(root_ / "outside.png");
    fs::create_symlink(root_ / "outside.png", folder_ / "out.png");
    fs::create_symlink("photo.png", folder_ / "in.png");
  }
  void TearDown() override { fs::remove_all(root_); }

  static void put(const fs::path& path) { std::ofstream(path) << "x"; }

  // The Error that folder_file throws for `name`.
  Error refusal(const std::string& name, bool must_exist = true) const {
    try {
      folder_file(folder_, name, must_exist);
    } catch (const Error& e) {
      return e;
    }
    ADD_FAILURE() << name << ": taken";
    return Error(ErrorKind::parse, "");
  }

  fs::path root_, folder_;
};

TEST_F(studio_folder, a_plain_name_is_the_file_in_the_folder) {
  EXPECT_EQ(folder_file(folder_, "photo.png", true), folder_ / "photo.png");
  EXPECT_EQ(folder_file(folder_, "new name-2.toml", false), folder_ / "new name-2.toml");
}

TEST_F(studio_folder, parent_absolute_nested_and_hidden_names_are_refused) {
  for (const std::string name : {"../outside.png", "..", "/etc/passwd", "sub/x.png", ".hidden.png",
                                 "", "a..b.png", "photo.png/", "-rf"}) {
    const Error e = refusal(name, false);
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument) << name;
    EXPECT_EQ(std::string(e.what()), "file: a plain name in --folder (got '" + name + "')");
  }
}

TEST_F(studio_folder, a_link_out_of_the_folder_is_refused_and_a_link_inside_is_followed) {
  const Error e = refusal("out.png");
  EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
  EXPECT_EQ(std::string(e.what()),
            "out.png: leads out of --folder (got " + (root_ / "outside.png").string() + ")");
  EXPECT_EQ(folder_file(folder_, "in.png", true), folder_ / "photo.png");
}

TEST_F(studio_folder, a_missing_file_or_a_folder_is_not_found) {
  EXPECT_EQ(refusal("missing.png").kind(), ErrorKind::not_found);
  EXPECT_STREQ(refusal("missing.png").what(), "missing.png: no such file in --folder");
  EXPECT_EQ(refusal("sub").kind(), ErrorKind::not_found);
}

TEST_F(studio_folder, listings_leave_out_links_out_hidden_files_and_other_kinds) {
  EXPECT_EQ(folder_files(folder_, {".png"}), (std::vector<std::string>{"in.png", "photo.png"}));
  EXPECT_EQ(folder_files(folder_, movie_extensions()), (std::vector<std::string>{"clip.MP4"}));
  EXPECT_TRUE(is_movie_name("clip.MP4"));
  EXPECT_FALSE(is_movie_name("photo.png"));
}

TEST_F(studio_folder, a_relative_source_is_found_here_or_in_the_folder) {
  const fs::path before = fs::current_path();
  fs::current_path(root_);
  EXPECT_EQ(find_source("outside.png", folder_), root_ / "outside.png");
  EXPECT_EQ(find_source("photo.png", folder_), folder_ / "photo.png");
  EXPECT_EQ(find_source("folder/photo.png", folder_), folder_ / "photo.png");
  EXPECT_EQ(find_source((folder_ / "photo.png").string(), folder_), folder_ / "photo.png");
  try {
    find_source("butterfly.jpg", folder_);
    ADD_FAILURE() << "found";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_EQ(std::string(e.what()), "--source butterfly.jpg: no such file (looked for " +
                                         (root_ / "butterfly.jpg").string() + " and " +
                                         (folder_ / "butterfly.jpg").string() + ")");
  }
  try {
    find_source("/nowhere/butterfly.jpg", folder_);
    ADD_FAILURE() << "found";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--source /nowhere/butterfly.jpg: no such file");
  }
  fs::current_path(before);
}

}  // namespace
}  // namespace ifsfx::app
