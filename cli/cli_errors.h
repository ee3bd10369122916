// SPDX-License-Identifier: Apache-2.0
// The libraries name their own parameters in messages ("quality: must be a positive number ...",
// "count: the number of buffers ...", "... allow_expansive accepts it ..."); the command line
// reports the flags the user typed instead ("--quality: ...", "-V: ...", "--allow-expansive").
#pragma once

#include <string>

namespace ifsfx::app {

// `message` with a leading library parameter ("quality: ...") and the parameters named inside it
// replaced by their command-line flags; other messages unchanged.
std::string with_flag_names(const std::string& message);

}  // namespace ifsfx::app
