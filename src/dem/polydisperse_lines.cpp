// SPDX-License-Identifier: BSD-3-Clause
// Every pair of types gets the single-pair deck of its own E*, R_eff, m_eff (deck.cpp's convention of each
// code); the code's entry (dem/dem_codes.hpp) makes the lines from those decks.
#include "dem/polydisperse_lines.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/contract_error.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

std::size_t pair_index(std::size_t i, std::size_t j, std::size_t n) {
  if (i > j) std::swap(i, j);
  // Pairs (0,0), (0,1), ..., (0,n-1), (1,1), ...: row i starts after i rows of n, n-1, ... entries.
  return i * n - i * (i - 1) / 2 + (j - i);
}

namespace {

double law_beta(const Pair& p, double dissipative_constant_s) {
  const double k = hertz_stiffness(p.effective_modulus_pa, p.effective_radius_m) / p.effective_mass_kg;
  return hertz_constants(k, dissipative_constant_s).beta;
}

// Spheres of any radii inside the range, each in its class (edges belong to both neighbours), get their
// class pair's coefficients; the code uses their true R_eff and m_eff.
// The grid has 8 subintervals per class, fewer (down to 2) for many classes so that it stays near 64 radii:
// the number of pairs grows with its square. Each ε is solved to 1e-8 min(ε, 1 - ε), far below the errors it
// measures (and cheaper than the default 1e-10).
BinningError binning_error(const PolydisperseResult& r, const SizeClasses& classes,
                           const std::vector<double>& speeds, CollisionSolver& solver) {
  const int kSubintervals = std::clamp(64 / static_cast<int>(r.types.size()), 2, 8);
  constexpr double tolerance = 1e-8;
  struct Sphere {
    std::size_t type;
    ParticleType particle;
  };
  std::vector<Sphere> grid;
  for (std::size_t k = 0; k < r.types.size(); ++k) {
    const double ratio = classes.edges_m[k + 1] / classes.edges_m[k];
    for (int s = 0; s <= kSubintervals; ++s) {
      ParticleType t = r.types[k];
      t.radius_m = s == kSubintervals ? classes.edges_m[k + 1]
                                      : classes.edges_m[k] * std::pow(ratio, double(s) / kSubintervals);
      grid.push_back({k, t});
    }
  }
  BinningError e;
  e.edges_m = classes.edges_m;
  e.grid_points_per_class = kSubintervals + 1;
  e.worst_relative_error = -1.0;
  for (std::size_t a = 0; a < grid.size(); ++a) {
    for (std::size_t b = a; b < grid.size(); ++b) {
      const Pair other = type_pair(grid[a].particle, grid[b].particle);
      const Deck& deck = r.pairs[pair_index(grid[a].type, grid[b].type, r.types.size())].deck;
      const double beta_code = deck_beta(deck, other);
      const double beta_law = law_beta(other, r.dissipative_constant_s);
      for (double v : speeds) {
        const double code = eps_for(beta_code, v, r.end, tolerance, solver);
        const double law = eps_for(beta_law, v, r.end, tolerance, solver);
        const double abs_error = std::fabs(code - law);
        const double relative = analysis::contract_error(code, law);
        e.worst_abs_error = std::max(e.worst_abs_error, abs_error);
        if (relative > e.worst_relative_error) {
          e.worst_relative_error = relative;
          e.radius1_m = grid[a].particle.radius_m;
          e.radius2_m = grid[b].particle.radius_m;
          e.velocity_m_s = v;
          e.eps_code = code;
          e.eps_law = law;
        }
      }
    }
  }
  return e;
}

std::vector<std::string> notes(const PolydisperseResult& r) {
  std::vector<std::string> n;
  n.push_back(r.calibrated
                  ? fmt::format("A = {:.10g} s calibrated for type pair (1,1) and given to every pair: one A "
                                "for the whole set (docs/dem.md)",
                                r.dissipative_constant_s)
                  : fmt::format("A = {:.10g} s given, the same for every pair: one A for the whole set "
                                "(docs/dem.md)",
                                r.dissipative_constant_s));
  // The tangential, friction and clamp notes of the single-pair deck hold for every pair; its last note (one
  // pair only) is what the per-pair lines remove.
  const std::vector<std::string>& first = r.pairs.front().deck.notes;
  n.insert(n.end(), first.begin(), first.end() - 1);
  n.emplace_back(
      "each type pair has its own E*, R_eff and m_eff: exact for spheres of exactly these radii and "
      "densities; a sphere of another size in a type gets A' = A m_eff'/m_eff");
  n.emplace_back(code_entry(r.code).polydisperse_note);
  n.emplace_back("set each type's diameter and density as listed: m_eff is part of the damping coefficients");
  return n;
}

}  // namespace

PolydisperseResult polydisperse_lines(const PolydisperseRequest& request) {
  const CodeEntry& code = code_entry(request.code);
  if (code.polydisperse == nullptr) throw InvalidInput(code.one_radius_only);
  if (request.types.empty()) throw InvalidInput("a polydisperse set needs at least one atom type");
  check_friction(request.friction);
  PolydisperseResult r;
  r.code = request.code;
  r.end = request.end;
  r.types = request.types;
  r.friction = request.friction;
  // A: the given one, or calibrated for two spheres of type 1.
  Material first;
  first.young_modulus_pa = r.types[0].young_modulus_pa;
  first.poisson_ratio = r.types[0].poisson_ratio;
  first.radius1_m = first.radius2_m = r.types[0].radius_m;
  first.density_kg_m3 = r.types[0].density_kg_m3;
  CollisionSolver solver;
  r.dissipative_constant_s =
      dissipative_constant(first, request.damping, request.end, request.tolerance, Method::automatic, solver);
  r.calibrated = !request.damping.dissipative_constant_s.has_value();
  r.reference_velocity_m_s = request.damping.velocity_m_s.value_or(1.0);
  const double v = r.reference_velocity_m_s;
  const std::vector<double> speeds =
      request.speeds_m_s.empty() ? std::vector<double>{v / 10.0, v, 10.0 * v} : request.speeds_m_s;
  const std::size_t n = r.types.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      TypePairLines p;
      p.type1 = static_cast<int>(i + 1);
      p.type2 = static_cast<int>(j + 1);
      p.pair = type_pair(r.types[i], r.types[j]);
      p.deck = make_deck(r.code, r.end, p.pair, r.dissipative_constant_s, v, r.friction);
      p.beta = deck_beta(p.deck, p.pair);
      for (double s : speeds) p.eps.push_back({s, eps_for(p.beta, s, r.end, request.tolerance, solver)});
      r.pairs.push_back(std::move(p));
    }
  }
  r.lines = code.polydisperse(r.pairs, n);
  r.notes = notes(r);
  if (request.classes) r.binning = binning_error(r, *request.classes, speeds, solver);
  return r;
}

CheckDeckRequest check_deck_request(const PolydisperseResult& r) {
  CheckDeckRequest request;
  request.code = r.code;
  request.lines = r.lines;
  request.type_count = static_cast<int>(r.types.size());
  for (const SpeedEps& e : r.pairs.front().eps) request.speeds_m_s.push_back(e.velocity_m_s);
  request.comments.push_back(fmt::format(
      "written by `restitution dem --code {}`: viscoelastic Hertz law, A = {:.10g} s, {} end, {} atom types",
      code_name(r.code), r.dissipative_constant_s, end_name(r.end), r.types.size()));
  for (const TypePairLines& p : r.pairs) {
    CheckPair c{p.type1, p.type2, p.pair, {}};
    for (const SpeedEps& e : p.eps) c.eps_restitution.push_back(e.eps);
    request.pairs.push_back(c);
    request.comments.push_back(fmt::format("type pair {},{}: radii {} and {} m, masses {} and {} kg", p.type1,
                                           p.type2, p.pair.radius1_m, p.pair.radius2_m, p.pair.mass1_kg,
                                           p.pair.mass2_kg));
  }
  return request;
}

}  // namespace restitution::dem
