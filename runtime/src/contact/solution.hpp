// A solved contact (or an iterate of the solver): the zones with their densities and the
// constant C, with the pressure and the gap anywhere in the half period (normalised x^, p^).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "narrow_gap.hpp"
#include "surface_model.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

class ContactSolution {
 public:
  ContactSolution(std::shared_ptr<const SurfaceModel> surface, Configuration configuration);
  // Its fields refer to its own configuration: neither copied nor moved.
  ContactSolution(const ContactSolution&) = delete;
  ContactSolution& operator=(const ContactSolution&) = delete;

  const Configuration& configuration() const { return configuration_; }
  const SurfaceModel& surface() const { return *surface_; }
  std::size_t zone_count() const { return configuration_.zones.size(); }
  const ZoneGeometry& zone(std::size_t k) const { return configuration_.zones[k].geometry; }
  bool full_contact() const;

  // The narrow gaps inside zone k (Configuration::narrow_gaps), in increasing x^: its pressure
  // is 0 in each, and the gap is the inner solution's.
  const std::vector<NarrowGap>& narrow_gaps(std::size_t k) const { return narrow_[k]; }
  // The zone holding x^ in [0, pi] (its ends included), or zone_count().
  std::size_t zone_at(double x) const;
  // p^ at x^ (any sign: |x^| <= pi), 0 off the zones.
  double pressure(double x) const;
  // The same at xs[0 .. count) into ps: a run of points in one zone is summed side by side.
  void pressures(const double* xs, double* ps, std::size_t count) const;
  // The part of p^ at x^ in zone k that its kink correction carries (0 without one).
  double kink_pressure(std::size_t k, double x) const;
  // The gap (2/E*)(Psi(x^) - C) - (y(x^) - y_top) off the zones, 0 on them.
  double gap(double x) const;
  // The same at xs[0 .. count) into gs: the points off the zones take one batch of the field
  // (FieldTree::evaluate, its reference their middle point), best for points close together.
  void gaps(const double* xs, double* gs, std::size_t count) const;
  // The load of zone k over its part of [0, pi]: pi h d_0 (the mirror image carries as much).
  double zone_load(std::size_t k) const;
  double load() const;  // P = 2 sum of zone_load

  // How many points, spread like Chebyshev's, sample zone k's pressure for its extrema: three
  // a node, but no more than three for each of 256 modes plus eight a half wavelength of the
  // shortest harmonic (a zone's nodes may outnumber its features many times over, where
  // they resolve a kink, and each point costs a sum over every node).
  int pressure_samples(std::size_t k) const;
  // Zone k's pressure at pressure_samples(k) + 1 such points, computed once (by whichever
  // thread asks first): over [a, b], ends included, for the verification and the largest
  // pressure alike (Span::whole); or short of a hundredth of the zone from a free end, where
  // the pressure goes like the root of the distance to it, for the refinement's comparisons
  // of two solutions, which take a solution's samples twice (Span::inside).
  struct PressureSamples {
    std::vector<double> xs, ps;
  };
  enum class Span { whole, inside };
  const PressureSamples& sampled_pressure(std::size_t k, Span span = Span::whole) const;

  // The total potential of the zones at x^ (off them).
  double potential(double x) const;

 private:
  // pressures() on the calling thread.
  void pressures_here(const double* xs, double* ps, std::size_t count) const;
  // Zone k's pressure at x^ without its narrow gaps.
  double merged_pressure(std::size_t k, double x) const;
  // The gap at x^ in zone k: its narrow gap's, or 0.
  double gap_in_zone(std::size_t k, double x) const;
  // The gap (2/E*)(Psi - C) - depth from Psi - C and the depth y(x^) - y_top at one point.
  double gap_of(double potential_less_C, double depth) const { return 2 / surface_->E * potential_less_C - depth; }

  std::shared_ptr<const SurfaceModel> surface_;
  Configuration configuration_;
  ZoneFields fields_;
  std::vector<double> ends_;                          // a_0, b_0, a_1, ...: for zone_at
  std::vector<std::vector<double>> pressure_series_;  // of each zone: bounded_pressure_series
  std::size_t longest_series_ = 0;
  std::vector<std::vector<NarrowGap>> narrow_;  // of each zone
  // Of each zone and span (at 2 k + span), once sampled_ at the same place has run.
  mutable std::vector<PressureSamples> samples_;
  std::unique_ptr<std::once_flag[]> sampled_;
};

}  // namespace wavecontact::detail
