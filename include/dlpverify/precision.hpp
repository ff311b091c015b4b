/// @file
/// The arithmetic a study's levels and its reference are computed in: IEEE double, or Extended
/// (QD's double-double, dlpverify/extended.hpp), whose round-off floor ½ ε √n ‖y‖ lies at
/// ε = 2^−104 instead of 2^−52.
#pragma once

#include <string>

namespace dlpverify {

/// Machine epsilon of double, 2^−52: the round-off floor ½ ε √n ‖y‖ (dlpverify/order.hpp).
inline constexpr double kDoubleEpsilon = 0x1p-52;
/// Machine epsilon of Extended, 2^−104 (QD's dd_real::_eps to its 15 printed digits).
inline constexpr double kExtendedEpsilon = 0x1p-104;

/// The arithmetic a study's levels (and its reference) are computed in.
enum class Precision {
  double_precision,  ///< IEEE double, the default
  extended,          ///< Extended (double-double)
};
/// "double" or "extended".
std::string to_string(Precision precision);
/// The machine epsilon of `precision`: kDoubleEpsilon or kExtendedEpsilon.
double epsilon_of(Precision precision);

}  // namespace dlpverify
