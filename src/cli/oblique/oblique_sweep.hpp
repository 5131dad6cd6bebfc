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

// The CSV's header line (without newline). A failed impact (ObliqueImpact::failure) is a row of NaN outputs
// whose last column, status, says "failed" ("solved" elsewhere).
const char* oblique_csv_header();
// The header and one row per impact; with a model, a first column tangential_model holding it (a scene's
// section sweeps several models into one table).
std::string oblique_csv(const std::vector<oblique::ObliqueImpact>& impacts);
std::string oblique_csv_header_with_model();
std::string oblique_csv_rows(const std::vector<oblique::ObliqueImpact>& impacts, const char* model);

// One model on Maw's diagram: the model and its sticking-limit e_t (NaN, and why, where its solve failed:
// the diagram then leaves the limit out).
struct MawModel {
  oblique::TangentialKind model{};
  double sticking_restitution = 0.0;
  std::string sticking_failure;
};
MawModel maw_model(const oblique::ObliqueSetup& setup);

// The arguments of scripts/plots/oblique_maw.py after its CSV and image: χ and ε of the gross-slip line, each
// model with its sticking limit.
std::vector<std::string> maw_plot_arguments(const oblique::ObliqueSetup& setup, double normal_restitution,
                                            const std::vector<MawModel>& models);

// The normal restitution of the gross-slip line of Maw's diagram: the first solved impact's (NaN: none).
double first_solved_restitution(const std::vector<oblique::ObliqueImpact>& impacts);

// Draws ψ₂ against ψ₁ of the CSV into image in each format, with the model's sticking limit (left out where
// its solve failed). Returns "" or why no plot was made (as run_plot_script); friction 0 has no ψ.
std::string plot_maw(const oblique::ObliqueSetup& setup, const MawModel& model, double normal_restitution,
                     const std::filesystem::path& csv, const std::filesystem::path& image,
                     const std::vector<std::string>& formats);

}  // namespace restitution::cli
