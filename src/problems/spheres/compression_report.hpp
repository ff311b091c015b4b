// The compression study's report (docs/hard-spheres.md, `dlpverify compress`): the header, the
// table of T2/T1 beside the laws, a sweep's tables and fitted slopes, the verdict's lines and the
// engine's events per second, each as the text a console shows and the JSON a file keeps.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "problems/spheres/compression.hpp"
#include "problems/spheres/event_rate.hpp"
#include "problems/spheres/expectation.hpp"
#include "problems/spheres/speed_sweep.hpp"

namespace dlpverify::compress {

// `given`, or the seed's seven volume ratios (half-edges 3.8 … 2.6 m) when it is empty.
std::vector<double> volume_ratios(const std::vector<double>& given);

// The gas, the walls, the model and the ensemble, then the packing and the mean free path.
std::string header_text(const Compression& c, int runs, std::uint64_t seed);
// Each row's simulated T2/T1 beside the analytic, Carnahan–Starling and seed values and the law
// of its regime, with its events, then the legend.
std::string table_text(const Compression& c, const std::vector<EnsembleRow>& rows);
// The rows as JSON, one object per volume ratio.
nlohmann::json rows_json(const Compression& c, const std::vector<EnsembleRow>& rows);
// The settings a result was computed with.
nlohmann::json settings_json(const Compression& c, int runs, std::uint64_t seed);

// A sweep's table per ratio with its fitted slope of ln error against ln `parameter`.
struct SweepReport {
  std::string text;
  nlohmann::json rows = nlohmann::json::array();
};
SweepReport sweep_report(const Compression& c, const std::vector<SweepRatio>& sweep, const char* parameter);

// Each miss of `verdict` and its PASS or FAIL line, at a relative `tolerance`.
std::string verdict_text(const CompressionVerdict& verdict, double tolerance);

// The engine's events per second, as text and JSON.
std::string bench_text(const EventRate& rate);
nlohmann::json bench_json(const EventRate& rate);

}  // namespace dlpverify::compress
