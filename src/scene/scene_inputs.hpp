// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The files a scene reads (a [[fit]]'s `data`). A scene may come from someone else: what it names is read
// only from within the scene's own folder, so that a scene cannot make `restitution run` open, and echo in an
// error, a file elsewhere on the machine (`../../../../etc/shadow`, or a symbolic link to /etc/passwd).
#include <filesystem>
#include <string>

namespace restitution::scene::detail {

class TomlReader;

// The file `written` (the value of `key`) names, relative to the folder of the scene file: its path after
// every symbolic link, for reading. Fails through `r` (InvalidInput naming the key, the value escaped) when
// the value is empty or absolute, climbs with '..', or leads (through a link) outside the scene's folder; the
// file is not opened for any of these checks.
std::filesystem::path contained_input(TomlReader& r, const std::string& key, const std::string& written);

}  // namespace restitution::scene::detail
