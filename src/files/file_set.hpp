// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Files that only make sense together, such as a gas deck's two inputs and the data file both read: written
// as one set, never a mixture of two.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace restitution::files {

struct SetMember {
  std::filesystem::path path;  // as named (output_target decides where it is written)
  const std::string* content = nullptr;
};

// Writes the members, in three steps:
//  1. every member into its own temporary (files/temporary_file.hpp); a failure (a full disk on the last
//     one) removes them all and throws IoError: the previous set is untouched;
//  2. the members of a previous set are removed, the last member first;
//  3. the temporaries are renamed onto their names in the order given.
// Whenever the process dies (SIGKILL included), the files present under the members' names are therefore part
// of one set: the previous one, or the new one without its last members. Give the member that users start
// from last (a deck's input): its presence says the set is whole. `stop_check` is called before each member's
// temporary and once after the last: whatever it throws (the command line's Interrupted for SIGINT, SIGTERM)
// removes the temporaries and is thrown on; from step 2 on it is not called, the set is finished.
// A member that is a device or stream (output_target's in_place) is written in place at step 3.
void write_file_set(const std::vector<SetMember>& members, const std::function<void()>& stop_check);

}  // namespace restitution::files
