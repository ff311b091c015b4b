// A user's explicit Butcher tableau, read from a TOML file (docs/cli.md, "dlpverify tableau"):
//
//   name = "midpoint"
//   order = 2
//   c = [0.0, 0.5]
//   b = [0.0, 1.0]
//   A = [[0.0, 0.0], [0.5, 0.0]]
//   b_embedded = [1.0, 0.0]      # optional, with embedded_order
//   embedded_order = 1
//
//   k_i = f(t + c_i Δt, y + Δt Σ_{j≤i} a_ij k_j),   y_{n+1} = y_n + Δt Σ_i b_i k_i
//
// The reader checks the shape and that the method is explicit or diagonally implicit (a_ij = 0
// for j > i; DIRK, SDIRK, ESDIRK when some a_ii ≠ 0), never the order conditions: a tableau that
// misses them is read as written (order_conditions.hpp judges).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace dlpverify {

// The most stages a tableau file may hold. The work of a step grows with s² (every a_ij), and
// that of `sharpness` and of the order conditions faster still (a 40-stage file kept sharpness
// busy past 90 s); the largest published methods in use stay far below: Fehlberg 7(8) has 13
// stages, SUNDIALS' largest explicit table (Verner 9(8)) 16.
inline constexpr std::size_t kMaxTableauStages = 32;

struct RuntimeTableau {
  std::string name;                    // `name`, for the reports
  std::string source;                  // the file it was read from, as given
  int order = 0;                       // the claimed order p
  std::vector<double> c, b;            // nodes c_i and weights b_i, s of each
  std::vector<std::vector<double>> a;  // a[i][j], s × s, zero above the diagonal
  std::vector<double> b_embedded;      // the embedded weights; empty when the file has none
  int embedded_order = 0;              // their claimed order; 0 when there are none
  int stages() const { return static_cast<int>(b.size()); }
  // Whether some a_ii ≠ 0: a diagonally implicit method, whose stages solve for themselves.
  bool implicit() const {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i][i] != 0.0) return true;
    return false;
  }
};

// Reads and checks a tableau file. Every malformed input (unreadable file, TOML syntax, a missing
// or unknown key, a wrong shape, a value that is not a finite number, a nonzero a_ij above the
// diagonal, an order below 1, more than kMaxTableauStages stages) throws InputError whose quantity names the file and the key.
RuntimeTableau read_tableau_file(const std::string& path);
// The same for the text of a file; `source` names it in errors.
RuntimeTableau parse_tableau(const std::string& text, const std::string& source);

}  // namespace dlpverify
