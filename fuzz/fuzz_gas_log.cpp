// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the reader of a gas deck's LAMMPS log (what `restitution gas --compare` trusts). Any text
// must give cooling curves made of complete lines of a deck, or InvalidInput naming the log; anything else is
// a finding. Every point the reader keeps is checked here on its own terms, not with the reader's code: its
// line exists and ends with a newline, holds exactly the fields the deck prints in their order, its numbers
// are whole tokens that strtod reads to the kept values, its run opened with a setup line of its law earlier
// in the log, and the times of a run increase. A cut line, `3.4e-4abc` or a run appended to another that the
// reader kept is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "gas_deck/gas_log.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;

void check(bool ok) {
  if (!ok) std::abort();
}

// The lines of `text` that end with a newline, without it (and without a CR before it); 1-based.
std::vector<std::string> terminated_lines(std::string_view text) {
  std::vector<std::string> lines{""};  // line 0 does not exist
  for (std::size_t begin = 0, end = 0; (end = text.find('\n', begin)) != std::string_view::npos;
       begin = end + 1) {
    std::string line(text.substr(begin, end - begin));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w(1);
  for (const char c : line) {
    if (c == ' ') {
      w.emplace_back();
    } else {
      w.back() += c;
    }
  }
  return w;
}

// The number after `key=` in `word`, read whole by strtod; NaN when it is not one.
double value(const std::string& word, const std::string& key) {
  check(word.rfind(key + "=", 0) == 0);
  const std::string text = word.substr(key.size() + 1);
  check(!text.empty() && text.find_first_of(" \t\n\v\f\r") == std::string::npos);
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  check(end == text.c_str() + text.size());
  return x;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // NOLINT: libFuzzer's API
  try {
    const gas_deck::GasLog log = gas_deck::read_gas_log(text, "fuzz.log");
    const std::vector<std::string> lines = terminated_lines(text);
    for (const gas_deck::CoolingCurve& curve : log.curves) {
      check(curve.law == "viscoelastic" || curve.law == "constant-eps");
      check(curve.setup.law == curve.law);
      check(curve.time_s.size() == curve.temperature_j.size() && curve.time_s.size() == curve.line.size());
      check(curve.time_s.size() <= gas_deck::kMostGasLogPrints);
      bool setup_seen = false;  // a setup line of this law before the first point
      for (std::size_t n = 1; !curve.line.empty() && n < curve.line.front(); ++n)
        setup_seen = setup_seen || lines[n].rfind("restitution-gas-setup law=" + curve.law + " ", 0) == 0;
      check(setup_seen || curve.line.empty());
      for (std::size_t k = 0; k < curve.time_s.size(); ++k) {
        check(curve.line[k] < lines.size());
        const std::vector<std::string> w = words(lines[curve.line[k]]);
        check(w.size() == 6 && w[0] == "restitution-gas" && w[1] == "law=" + curve.law);
        check(value(w[2], "time_s") == curve.time_s[k] && curve.time_s[k] >= 0.0);
        check(value(w[3], "temperature_j") == curve.temperature_j[k] && curve.temperature_j[k] > 0.0);
        check(value(w[4], "timestep_s") > 0.0);
        check(w[5].rfind("step=", 0) == 0 && w[5].size() > 5 &&
              w[5].find_first_not_of("0123456789", 5) == std::string::npos);
        check(k == 0 || (curve.time_s[k] > curve.time_s[k - 1] && curve.line[k] > curve.line[k - 1]));
      }
    }
  } catch (const InvalidInput& e) {
    check(std::string(e.what()).find("fuzz.log") != std::string::npos);
  }
  return 0;
}
