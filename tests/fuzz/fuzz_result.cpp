// libFuzzer target: a result file given to `dlpverify plot` — converge/check or precision JSON, a
// --per-particle or --history CSV. The input is the file's bytes: its kind is found as the plot
// command finds it (cli::read_result), it is read, its figure built (alone, and overlaid with
// itself) and the gnuplot script of that figure written out — everything `plot` does but run
// gnuplot. Bad input must end as an InputError (exit 2); any other exception (the script's
// tripwire included), a crash, a hang or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/plot_command.hpp"
#include "dlpverify/errors.hpp"
#include "plot/figures.hpp"

namespace {

using namespace dlpverify;

plot::Figure figure_of(const cli::ResultFile& result, const std::string& bytes, std::size_t copies, bool relative) {
  const PlotOptions options{"figure.png", "", "-o", relative, {}};
  if (result.kind == cli::ResultKind::convergence)
    return plot::convergence_figure(std::vector<nlohmann::json>(copies, result.json), options);
  if (result.kind == cli::ResultKind::work_precision)
    return plot::work_precision_figure(std::vector<nlohmann::json>(copies, result.json), options);
  std::istringstream in(bytes);
  const CsvTable table = result.kind == cli::ResultKind::per_particle ? plot::read_per_particle_csv(in, "result.csv")
                                                                      : plot::read_history_csv(in, "result.csv");
  const std::vector<CsvTable> tables(copies, table);
  return result.kind == cli::ResultKind::per_particle ? plot::error_vs_xi_figure(tables, options)
                                                      : plot::error_history_figure(tables, options);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream in(bytes);
    const cli::ResultFile result = cli::read_result(in, "result");
    for (std::size_t copies : {1, 2}) {
      const plot::FigureScript script = plot::figure_script(figure_of(result, bytes, copies, copies == 2));
      (void)script.script.render();
    }
  } catch (const InputError&) {
  }
  return 0;
}
