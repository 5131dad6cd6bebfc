// SPDX-License-Identifier: BSD-3-Clause
#include "dem/process_output.hpp"

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace restitution::dem {

std::string output_of(const std::string& command) {
  std::string out;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) out += buffer.data();
  return out;
}

std::string output_with_input_file(const std::string& input, const std::string& suffix,
                                   const std::function<std::string(const std::string& path)>& command_for) {
  std::string name = "/tmp/restitution-dem-XXXXXX" + suffix;
  const int fd = mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0) throw std::runtime_error("cannot create a temporary input file for the DEM code");
  close(fd);
  std::ofstream(name) << input;
  std::string out = output_of(command_for(name));
  std::filesystem::remove(name);
  return out;
}

TaggedEps tagged_eps(const std::string& output, const std::string& tag, std::size_t count) {
  TaggedEps t;
  t.eps.assign(count, NAN);
  t.gap_m.assign(count, NAN);
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string word;
    std::size_t i = 0;
    double e = NAN;
    double gap = NAN;
    if (fields >> word && word == tag && fields >> i >> e >> gap && i < count) {
      t.eps[i] = e;
      t.gap_m[i] = gap;
    }
  }
  return t;
}

}  // namespace restitution::dem
