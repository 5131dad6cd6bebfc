// SPDX-License-Identifier: BSD-3-Clause
#include "dem/process_output.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"

namespace restitution::dem {

std::string output_of(const std::string& command) {
  std::string out;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) out += buffer.data();
  return out;
}

ChildRun output_with_input_file(
    const std::string& input, const std::string& suffix,
    const std::function<std::vector<std::string>(const std::string& path)>& command_for) {
  std::string name = "/tmp/restitution-dem-XXXXXX" + suffix;
  const int fd = mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0) throw IoError("cannot create a temporary input file for the DEM code");
  close(fd);
  {
    std::ofstream file(name);
    file << input;
    if (!file.flush()) {
      std::filesystem::remove(name);
      throw IoError(fmt::format("cannot write the DEM code's input file {}", name));
    }
  }
  ChildRun run = run_child(command_for(name), ChildOutput::capture);
  std::filesystem::remove(name);
  return run;
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

std::string code_run_failure(const ChildRun& run, const std::string& program, const TaggedEps& read) {
  if (!child_succeeded(run.status)) {
    std::string last;
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);) {
      if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    }
    return fmt::format("'{}' {}{}", quoted_excerpt(program), child_status_text(run.status),
                       last.empty() ? "" : fmt::format(" (its last line: '{}')", quoted_excerpt(last)));
  }
  std::size_t missing = 0;
  for (const double e : read.eps) missing += std::isfinite(e) ? 0 : 1;
  if (missing == 0) return "";
  return fmt::format("'{}' printed no eps for {} of its {} collisions", quoted_excerpt(program), missing,
                     read.eps.size());
}

}  // namespace restitution::dem
