// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The restitution library in one include: contact laws, the collision solver and its engines, units and
// materials, calibration, the analytic series with the published coefficient tables, and the certified
// fast ε(ζ) table.
#include "restitution/build_info.hpp"
#include "restitution/calibration.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution/fit.hpp"
#include "restitution/fit_csv.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"
#include "restitution/series_tables.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"
