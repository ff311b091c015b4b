/// @file
/// The DLP particle cloud (docs/model.md §1–§2) as a ready problem: a named case on a lattice
/// cloud with the default parameters of docs/model.md §8. For your own parameters, build a
/// DlpProblem from the headers under src/problems/dlp (they are internal, not installed).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dlpverify/problem.hpp"
#include "dlpverify/study.hpp"

/// The DLP particle cloud as ready problems (docs/model.md §1–§2).
namespace dlpverify::dlp {

/// The lattice cloud a case is set on: particles at the integer lattice points of a sphere (or shell).
struct CloudShape {
  int outer = 10;                  ///< R_out in lattice spacings (100: the seed's 4,187,856 particles)
  bool shell = false;              ///< a shell R_out − 5 ≤ r ≤ R_out instead of the sphere 1 ≤ r ≤ R_out
  double expansion_speed = 100.0;  ///< u_s [m/s]
};

/// similarity, gravity, drag, drag-gravity-vertical, drag-heat, burn, drag-gravity, drag-law, full.
std::vector<std::string> case_names();
/// The study defaults under which the case's expected order shows. Throws InputError naming the case.
StudyDefaults case_defaults(const std::string& case_name);
/// The case's problem on the lattice cloud. Throws InputError naming an unknown case.
std::unique_ptr<Problem> make_problem(const std::string& case_name, const CloudShape& cloud = {});

}  // namespace dlpverify::dlp
