// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which engine computes which method, with the engine's name and its smallest tolerance: the one place that
// maps a Method to an engine (src/solver/engine_registry.cpp holds the table). CollisionSolver and the
// checks of solver/ consult it and include no engine's own headers; each engine's limits sit in its check().
#include <memory>
#include <vector>

#include "engine/engine.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution {

struct EngineInfo {
  const char* name = "";       // "CVODE" | "Taylor", in messages
  double min_tolerance = 0.0;  // the smallest tolerance the engine accepts
};

// The engine that computes `method` (automatic: CVODE, which chooses BDF or Adams itself).
const EngineInfo& engine_of(Method method);

// One instance of each engine, each created at its first use and reused after (engines keep integrator
// memory across solves); one set per thread, as for CollisionSolver.
class Engines {
 public:
  Engines();
  ~Engines();
  Engines(const Engines&) = delete;
  Engines& operator=(const Engines&) = delete;
  Engines(Engines&&) = delete;
  Engines& operator=(Engines&&) = delete;

  Engine& operator()(Method method);

 private:
  std::vector<std::unique_ptr<Engine>> engines_;  // one per entry of the table in registry.cpp
};

}  // namespace restitution
