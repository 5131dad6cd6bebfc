// SPDX-License-Identifier: BSD-3-Clause
#include "reference/reference_solution.hpp"

#include <fmt/core.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "restitution/errors.hpp"
#include "restitution/restitution.hpp"
#include "taylor/taylor_collision.hpp"

namespace restitution {
namespace {

using Real = __float128;
using taylor::TaylorOutcome;
using taylor::TaylorPoint;
using taylor::TaylorSettings;

// Two runs that differ in order and tolerance; the second is the one stored. float128 carries ~34 digits,
// so 1e-33 is as tight as a local error can usefully be.
struct Run {
  int order;
  double tolerance;
};
constexpr Run kCoarse{32, 1e-31};
constexpr Run kFine{40, 1e-33};

TaylorSettings hertz_settings(double zeta, EndSet ends, const Run& run) {
  TaylorSettings s;
  s.order = run.order;
  s.tolerance = run.tolerance;
  s.ends = ends;
  const bool naive = ends.contains(CollisionEnd::naive);
  const double z = std::max(zeta, 1.0);
  // Floors far below every value that matters, so that the control is relative.
  const double velocity = naive ? std::pow(z, -5.0) : std::pow(z, -5.0 / 3.0);
  const double x = naive ? std::pow(z, -4.0) : std::pow(z, -2.0 / 3.0);
  s.compression_floor = {1e-6, 1e-6 * velocity, 1e-6 / z};
  s.time_floor = {1e-6 * std::sqrt(x), 1e-6 * velocity, 1e-6 / z};
  s.end_switch_u_max = 1.0 / (z * z);
  s.time_limit = 1000.0 * (1.0 + zeta) * (1.0 + std::log1p(zeta));
  s.max_steps = 50000000;
  return s;
}

ReferenceEnd end_of(Real damping, bool hertz, const TaylorPoint<Real>& p) {
  const Real x = p.x > 0 ? p.x : Real(0);
  const Real elastic = hertz ? Real(0.4) * x * x * sqrtq(x) : x * x / 2;
  const auto values = taylor::end_values(damping, elastic, p);
  return {values.eps, values.one_minus_eps, p.tau, x};
}

ReferenceSolution solution_of(double parameter, Real damping, bool hertz, const TaylorOutcome<Real>& out) {
  ReferenceSolution s;
  s.parameter = parameter;
  s.tau_max = out.tau_max;
  s.x_max = out.x_max;
  for (const CollisionEnd end : kCollisionEnds) {
    if (out.ends[end]) s.ends[end] = end_of(damping, hertz, *out.ends[end]);
  }
  s.steps = out.steps;
  return s;
}

double relative(Real a, Real b, Real scale) {
  if (scale == 0) return a == b ? 0.0 : HUGE_VAL;
  return static_cast<double>(fabsq(a - b) / fabsq(scale));
}

double end_difference(const std::optional<ReferenceEnd>& a, const std::optional<ReferenceEnd>& b) {
  if (a.has_value() != b.has_value()) return HUGE_VAL;
  if (!a) return 0.0;
  const Real scale = fminq(b->eps, b->one_minus_eps);
  return std::max({relative(a->eps, b->eps, scale), relative(a->one_minus_eps, b->one_minus_eps, scale),
                   relative(a->tau, b->tau, b->tau),
                   b->x == 0 ? relative(a->x, b->x, 1) : relative(a->x, b->x, b->x)});
}

// The finer solution with the agreement of the two; throws if they disagree beyond kReferenceAgreement.
ReferenceSolution compare(ReferenceSolution coarse, ReferenceSolution fine, const char* law) {
  fine.agreement = std::max({relative(coarse.tau_max, fine.tau_max, fine.tau_max),
                             relative(coarse.x_max, fine.x_max, fine.x_max),
                             end_difference(coarse.ends[CollisionEnd::naive], fine.ends[CollisionEnd::naive]),
                             end_difference(coarse.ends[CollisionEnd::delayed_recovery],
                                            fine.ends[CollisionEnd::delayed_recovery])});
  if (!(fine.agreement <= kReferenceAgreement)) {
    throw NumericalFailure(
        fmt::format("reference solution for {} at parameter {}: the two orders differ by {:g} > {:g}", law,
                    fine.parameter, fine.agreement, kReferenceAgreement));
  }
  return fine;
}

std::string text(Real value) {
  char buffer[64];
  quadmath_snprintf(buffer, sizeof buffer, "%.33Qe", value);
  return buffer;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

constexpr const char* kHeader =
    "zeta,max_compression_tau,max_compression_x,naive_eps,naive_one_minus_eps,naive_tau,naive_x,"
    "delayed_recovery_eps,delayed_recovery_one_minus_eps,delayed_recovery_tau,delayed_recovery_x,agreement,"
    "steps";

}  // namespace

ReferenceSolution hertz_reference(double zeta, EndSet ends) {
  if (!std::isfinite(zeta) || zeta < 0)
    throw InvalidInput(fmt::format("zeta must be finite and >= 0, got {}", zeta));
  if (zeta > kReferenceNaiveZetaMax) ends.erase(CollisionEnd::naive);
  if (ends.empty())
    throw InvalidInput(
        fmt::format("no end to compute at zeta={}: the reference holds the naive end only for "
                    "zeta <= {:g}",
                    zeta, kReferenceNaiveZetaMax));
  auto solve = [&](const Run& run) {
    taylor::TaylorCollision<Real> collision(hertz_settings(zeta, ends, run), zeta);
    return solution_of(zeta, zeta, true, collision.hertz(Real(zeta)));
  };
  return compare(solve(kCoarse), solve(kFine), "viscoelastic-hertz");
}

ReferenceSolution dashpot_reference(double damping_ratio) {
  if (!std::isfinite(damping_ratio) || damping_ratio <= 0)
    throw InvalidInput(fmt::format("damping-ratio must be finite and > 0, got {}", damping_ratio));
  auto solve = [&](const Run& run) {
    TaylorSettings s;
    s.order = run.order;
    s.tolerance = run.tolerance;
    if (damping_ratio >= 1.0) s.ends.erase(CollisionEnd::naive);
    s.time_floor = {1e-8, 1e-8, 1e-8};
    s.time_limit = 1000.0 * (1.0 + damping_ratio);
    taylor::TaylorCollision<Real> collision(s, damping_ratio);
    const Real damping = 2 * Real(damping_ratio);
    return solution_of(damping_ratio, damping, false, collision.dashpot(damping, Real(1)));
  };
  return compare(solve(kCoarse), solve(kFine), "linear-dashpot");
}

std::vector<ReferenceSolution> hertz_references(
    const std::vector<double>& zetas, const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<ReferenceSolution> solutions;
  for (const double zeta : zetas) {
    solutions.push_back(hertz_reference(zeta));
    progress(solutions.size(), zetas.size());
  }
  return solutions;
}

std::vector<double> reference_zeta_grid() {
  std::vector<double> grid{0.0};
  for (int k = -32; k <= 16; ++k) grid.push_back(std::pow(10.0, k / 4.0));
  return grid;
}

std::string reference_csv(const std::vector<ReferenceSolution>& solutions) {
  std::string out =
      "# Reference solutions of x'' + zeta x' sqrt(x) + x^{3/2} = 0, x(0) = 0, x'(0) = 1 (natural units): "
      "Taylor method in __float128, two orders agreeing to 'agreement'. Regenerate: restitution reference "
      "--out data/reference_solutions.csv\n";
  // The code that computed it (docs/release.md); CVODE takes no part in the reference.
  out += fmt::format("# Computed by restitution {} (commit {}).\n", library_version().version,
                     library_version().commit);
  out += kHeader;
  out += '\n';
  for (const ReferenceSolution& s : solutions) {
    out += fmt::format("{:.17g},{},{}", s.parameter, text(s.tau_max), text(s.x_max));
    for (const CollisionEnd e : kCollisionEnds) {
      if (const auto& end = s.ends[e]) {
        out += fmt::format(",{},{},{},{}", text(end->eps), text(end->one_minus_eps), text(end->tau),
                           text(end->x));
      } else {
        out += ",,,,";
      }
    }
    out += fmt::format(",{:.3g},{}\n", s.agreement, s.steps);
  }
  return out;
}

std::vector<ReferenceRow> read_reference_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInput(fmt::format("cannot read the reference file {}", path.string()));
  std::vector<ReferenceRow> rows;
  std::string line;
  int number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      if (line != kHeader) throw InvalidInput(fmt::format("{}:{}: unexpected header", path.string(), number));
      header_seen = true;
      continue;
    }
    const std::vector<std::string> f = split(line);
    if (f.size() != 13) throw InvalidInput(fmt::format("{}:{}: expected 13 fields", path.string(), number));
    auto value = [&](std::size_t i) {
      char* end = nullptr;
      const double v = std::strtod(f[i].c_str(), &end);
      if (f[i].empty() || *end != '\0')
        throw InvalidInput(fmt::format("{}:{}: field {} is not a number", path.string(), number, i + 1));
      return v;
    };
    auto end_at = [&](std::size_t i) -> std::optional<ReferenceEndValues> {
      if (f[i].empty()) return std::nullopt;
      return ReferenceEndValues{value(i), value(i + 1), value(i + 2), value(i + 3)};
    };
    ReferenceRow row{value(0), value(1), value(2), {}, value(11)};
    row.ends[CollisionEnd::naive] = end_at(3);
    row.ends[CollisionEnd::delayed_recovery] = end_at(7);
    rows.push_back(row);
  }
  if (!header_seen) throw InvalidInput(fmt::format("{}: no header line", path.string()));
  return rows;
}

std::filesystem::path reference_file_in(const std::filesystem::path& source_dir) {
  return source_dir / "data" / "reference_solutions.csv";
}

}  // namespace restitution
