// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/material.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

void require_positive(double value, const char* key) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("material: {} must be finite and > 0, got {}", key, value));
  }
}

// 1999 paper Eq. 5 (A from the viscosities); it divides by ν², so ν = 0 has no finite A.
double dissipative_constant_from_viscosities(const Viscosities& v, double young_pa, double nu) {
  if (!std::isfinite(v.eta1_pa_s) || !std::isfinite(v.eta2_pa_s) || v.eta1_pa_s < 0.0 || v.eta2_pa_s < 0.0 ||
      3.0 * v.eta2_pa_s + 2.0 * v.eta1_pa_s <= 0.0) {
    throw InvalidInput(fmt::format("material: viscosities must be finite, >= 0 and not both 0, got [{}, {}]",
                                   v.eta1_pa_s, v.eta2_pa_s));
  }
  if (nu == 0.0) {
    throw InvalidInput(
        "material: poisson_ratio = 0 gives no finite A from viscosities; give dissipative_constant");
  }
  const double shear = 3.0 * v.eta2_pa_s - v.eta1_pa_s;
  return shear * shear / (3.0 * (3.0 * v.eta2_pa_s + 2.0 * v.eta1_pa_s)) * (1.0 - nu * nu) *
         (1.0 - 2.0 * nu) / (young_pa * nu * nu);
}

}  // namespace

ElasticConstants elastic_constants(const Material& m) {
  require_positive(m.young_modulus_pa, "young_modulus");
  if (!std::isfinite(m.poisson_ratio) || m.poisson_ratio <= -1.0 || m.poisson_ratio >= 0.5) {
    throw InvalidInput(fmt::format("material: poisson_ratio must be in (-1, 0.5), got {}", m.poisson_ratio));
  }
  require_positive(m.radius1_m, "radius1");
  require_positive(m.radius2_m, "radius2");

  double mass1 = 0.0;
  double mass2 = 0.0;
  if (m.mass1_kg || m.mass2_kg) {
    if (!m.mass1_kg || !m.mass2_kg) throw InvalidInput("material: give both mass1 and mass2, or density");
    if (m.density_kg_m3) throw InvalidInput("material: give either density or mass1 and mass2, not both");
    require_positive(*m.mass1_kg, "mass1");
    require_positive(*m.mass2_kg, "mass2");
    mass1 = *m.mass1_kg;
    mass2 = *m.mass2_kg;
  } else {
    if (!m.density_kg_m3) throw InvalidInput("material: give density, or mass1 and mass2");
    require_positive(*m.density_kg_m3, "density");
    mass1 = sphere_mass_kg(m.radius1_m, *m.density_kg_m3);
    mass2 = sphere_mass_kg(m.radius2_m, *m.density_kg_m3);
  }

  ElasticConstants e;
  e.effective_radius_m = m.radius1_m * m.radius2_m / (m.radius1_m + m.radius2_m);
  e.effective_mass_kg = mass1 * mass2 / (mass1 + mass2);
  e.elastic_constant = hertz_stiffness(m.young_modulus_pa, m.poisson_ratio, e.effective_radius_m);
  e.k = e.elastic_constant / e.effective_mass_kg;
  if (!std::isfinite(e.k) || e.k <= 0.0) {
    throw InvalidInput("material: the data give k = rho/m_eff outside the range of double");
  }
  return e;
}

MaterialConstants material_constants(const Material& m) {
  MaterialConstants c;
  c.elastic = elastic_constants(m);
  if (m.dissipative_constant_s.has_value() == m.viscosities.has_value()) {
    throw InvalidInput("material: give exactly one of dissipative_constant and viscosities");
  }
  if (m.dissipative_constant_s) {
    if (!std::isfinite(*m.dissipative_constant_s) || *m.dissipative_constant_s < 0.0) {
      throw InvalidInput(fmt::format("material: dissipative_constant must be finite and >= 0, got {}",
                                     *m.dissipative_constant_s));
    }
    c.dissipative_constant_s = *m.dissipative_constant_s;
  } else {
    c.dissipative_constant_s =
        dissipative_constant_from_viscosities(*m.viscosities, m.young_modulus_pa, m.poisson_ratio);
  }
  c.hertz = hertz_constants(c.elastic.k, c.dissipative_constant_s);
  return c;
}

}  // namespace restitution
