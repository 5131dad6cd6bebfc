#include "dem/process_output.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace restitution::dem {

std::string output_of(const std::string& command) {
  std::string out;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) out += buffer.data();
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
