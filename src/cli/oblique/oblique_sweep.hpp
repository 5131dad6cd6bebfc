// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What `restitution oblique` and a scene's [[oblique]] section write of a sweep over impact angles and
// initial spins: the CSV (one row per (angle, spin) pair) and Maw, Barber & Fawcett's diagram
// (scripts/plots/oblique_maw.py).
#include <filesystem>
#include <string>
#include <vector>

#include "restitution_oblique/oblique_study.hpp"

namespace restitution::cli {

// "FROM:TO:N": N >= 2 angles from FROM to TO (degrees) evenly spaced, both ends included; throws InvalidInput
// naming --angle-range and what is wrong.
std::vector<double> angle_range(const std::string& text);

// The CSV's header line (without newline).
const char* oblique_csv_header();
// The header and one row per impact.
std::string oblique_csv(const std::vector<oblique::ObliqueImpact>& impacts);

// One model's sweep on Maw's diagram: its CSV (oblique_csv), the model and its sticking-limit e_t.
struct MawSeries {
  std::filesystem::path csv;
  oblique::TangentialKind model = oblique::TangentialKind::linear_history;
  double sticking_restitution = 0.0;
};

// The series of a setup and its sweep, written to csv_path.
MawSeries maw_series(const oblique::ObliqueSetup& setup, const std::filesystem::path& csv_path);

// Draws ψ₂ against ψ₁ for every series (the first one's χ and ε give the gross-slip line) into image in each
// format. Returns "" or why no plot was made (as run_plot_script).
std::string plot_maw(const oblique::ObliqueSetup& setup, double normal_restitution,
                     const std::vector<MawSeries>& series, const std::filesystem::path& image,
                     const std::vector<std::string>& formats);

}  // namespace restitution::cli
