// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/placement.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "restitution/errors.hpp"

namespace restitution::gas_deck {
namespace {

// Attempts per sphere before giving up: at phi <= 0.3 random sequential addition needs a few on average.
constexpr int kAttemptsPerSphere = 10000;

// Cells at least one diameter wide: every neighbour within a diameter is in the 27 cells around.
class CellList {
 public:
  CellList(double box_m, double diameter_m)
      : box_(box_m),
        cells_(std::max(1, static_cast<int>(std::floor(box_m / diameter_m)))),
        width_(box_m / cells_),
        members_(static_cast<std::size_t>(cells_) * cells_ * cells_) {}

  [[nodiscard]] bool fits(const Vec3& p, const std::vector<Vec3>& points, double diameter_m) const {
    const std::array<int, 3> c = cell_of(p);
    const int reach = cells_ >= 3 ? 1 : 0;  // fewer than three cells: every cell is a neighbour
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          for (std::size_t j : members_[index({c[0] + dx, c[1] + dy, c[2] + dz})]) {
            if (periodic_distance_squared(p, points[j]) < diameter_m * diameter_m) return false;
          }
        }
    if (cells_ < 3) {
      for (const auto& q : points)
        if (periodic_distance_squared(p, q) < diameter_m * diameter_m) return false;
    }
    return true;
  }
  void add(const Vec3& p, std::size_t id) { members_[index(cell_of(p))].push_back(id); }

 private:
  [[nodiscard]] std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = std::min(cells_ - 1, static_cast<int>(p[k] / width_));
    return c;
  }
  [[nodiscard]] std::size_t index(std::array<int, 3> c) const {
    for (int& k : c) k = ((k % cells_) + cells_) % cells_;
    return (static_cast<std::size_t>(c[0]) * cells_ + c[1]) * cells_ + c[2];
  }
  [[nodiscard]] double periodic_distance_squared(const Vec3& a, const Vec3& b) const {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      double d = std::abs(a[k] - b[k]);
      d = std::min(d, box_ - d);
      sum += d * d;
    }
    return sum;
  }

  double box_;
  int cells_;
  double width_;
  std::vector<std::vector<std::size_t>> members_;
};

}  // namespace

std::vector<Vec3> random_positions(std::size_t count, double diameter_m, double box_m, std::uint64_t seed) {
  if (count < 2) throw InvalidInput(fmt::format("--particles must be at least 2, got {}", count));
  const double phi =
      static_cast<double>(count) * std::numbers::pi / 6.0 * std::pow(diameter_m, 3) / std::pow(box_m, 3);
  if (!(phi > 0.0 && phi <= kMaxPackingFraction)) {
    throw InvalidInput(
        fmt::format("--packing-fraction must be in (0, {}] (random placement jams near 0.38), got {:.4g}",
                    kMaxPackingFraction, phi));
  }
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(0.0, box_m);
  CellList cells(box_m, diameter_m);
  std::vector<Vec3> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    for (int attempt = 0;; ++attempt) {
      if (attempt == kAttemptsPerSphere)
        throw InvalidInput(
            fmt::format("no room found for sphere {} of {} at packing fraction {:.4g}", i + 1, count, phi));
      const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
      if (cells.fits(p, points, diameter_m)) {
        cells.add(p, points.size());
        points.push_back(p);
        break;
      }
    }
  }
  return points;
}

std::vector<Vec3> maxwellian_velocities(std::size_t count, double rms_speed_m_s, std::uint64_t seed) {
  if (!(rms_speed_m_s > 0.0 && std::isfinite(rms_speed_m_s)))
    throw InvalidInput(fmt::format("--rms-speed must be > 0 m/s, got {}", rms_speed_m_s));
  // Another stream than the positions': a different seed sequence from the same seed.
  std::seed_seq sequence{seed, std::uint64_t{0x9e3779b97f4a7c15}};
  std::mt19937_64 random(sequence);
  std::normal_distribution<double> component(0.0, rms_speed_m_s);
  std::vector<Vec3> v(count);
  Vec3 mean{};
  for (auto& u : v)
    for (int k = 0; k < 3; ++k) {
      u[k] = component(random);
      mean[k] += u[k] / static_cast<double>(count);
    }
  double sum_squares = 0.0;
  for (auto& u : v)
    for (int k = 0; k < 3; ++k) {
      u[k] -= mean[k];
      sum_squares += u[k] * u[k];
    }
  const double scale = rms_speed_m_s / std::sqrt(sum_squares / (3.0 * static_cast<double>(count)));
  for (auto& u : v)
    for (double& c : u) c *= scale;
  return v;
}

}  // namespace restitution::gas_deck
