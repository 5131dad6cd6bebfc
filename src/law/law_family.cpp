// SPDX-License-Identifier: BSD-3-Clause
// The members of the contact-law family: a new member is one entry of kMembers (docs/contact_laws.md).
#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

struct Member {
  LawKind kind;
  const char* name;
  LawExponents exponents;  // elastic force x^a, damping x^b x'
  LawParameter parameter;  // what results are labelled with: ζ, or the dash-pot's damping ratio r = ζ/2
};

constexpr LawParameter kZeta{"zeta", 1.0};
constexpr Member kMembers[] = {
    {LawKind::viscoelastic_hertz, "viscoelastic-hertz", {1.5, 0.5}, kZeta},
    {LawKind::linear_dashpot, "linear-dashpot", {1.0, 0.0}, {"damping-ratio", 2.0}},
    {LawKind::tsuji_hertz, "tsuji-hertz", {1.5, 0.25}, kZeta},
    {LawKind::hertz_constant_damping, "hertz-constant-damping", {1.5, 0.0}, kZeta},
};

const Member& member(LawKind kind) {
  for (const Member& m : kMembers) {
    if (m.kind == kind) return m;
  }
  throw InvalidInput(fmt::format("unknown contact law kind {}", static_cast<int>(kind)));
}

}  // namespace

const char* law_name(LawKind kind) {
  return member(kind).name;
}

LawKind law_from_name(const std::string& name) {
  std::string names;
  for (const Member& m : kMembers) {
    if (name == m.name) return m.kind;
    names += names.empty() ? m.name : fmt::format(", {}", m.name);
  }
  throw InvalidInput(fmt::format("law must be one of {}, got '{}'", names, name));
}

const std::vector<std::string>& law_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Member& m : kMembers) out.emplace_back(m.name);
    return out;
  }();
  return names;
}

LawParameter law_parameter(LawKind kind) {
  return member(kind).parameter;
}

LawExponents law_exponents(LawKind kind) {
  return member(kind).exponents;
}

double speed_exponent(LawKind kind) {
  const auto [a, b] = law_exponents(kind);
  return b + (b + 1.0) * (1.0 - a) / (1.0 + a);
}

bool speed_independent(LawKind kind) {
  return std::abs(speed_exponent(kind)) < 1e-12;
}

double naive_end_critical_zeta(LawKind kind) {
  return 2.0 * std::sqrt(law_exponents(kind).damping + 1.0);
}

bool has_dissipative_constant(LawKind kind) {
  return kind == LawKind::viscoelastic_hertz;
}

}  // namespace restitution
