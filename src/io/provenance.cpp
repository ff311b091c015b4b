#include "io/provenance.hpp"

#include <chrono>
#include <ctime>

#include <Eigen/Core>
#include <gsl/gsl_version.h>
#include <omp.h>
#include <sundials/sundials_config.h>
#include <unistd.h>

#include "build_info.hpp"
#include "io/format.hpp"

namespace dlpverify {

namespace {
std::string eigen_version() {
  return std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION);
}
std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}
std::string host_name() {
  char buffer[256] = {0};
  return ::gethostname(buffer, sizeof buffer - 1) == 0 ? buffer : "unknown";
}
}  // namespace

nlohmann::json provenance(const std::string& command_line) {
  return {{"version", build::version},
          {"git_commit", build::git_commit},
          {"build_type", build::build_type},
          {"compiler", std::string("g++ ") + __VERSION__},
          {"flags", build::cxx_flags},
          {"sundials", SUNDIALS_VERSION},
          {"eigen", eigen_version()},
          {"gsl", GSL_VERSION},
          {"host", host_name()},
          {"threads", omp_get_max_threads()},
          {"date", utc_now()},
          {"command_line", command_line}};
}

std::string version_line() {
  return std::string("dlpverify ") + build::version + " (commit " + build::git_commit + ", SUNDIALS " +
         SUNDIALS_VERSION + ", Eigen " + eigen_version() + ", GSL " + GSL_VERSION + ")";
}

std::string csv_header(const std::string& what, const nlohmann::json& provenance, const nlohmann::json& options) {
  // Each value on its one line, in UTF-8: JSON's escapes (a newline in an argument as \n, bytes
  // that are not UTF-8 as U+FFFD), without a string's quotes.
  auto field = [&provenance](const char* key) {
    if (!provenance.contains(key)) return std::string("?");
    const std::string text = json_text(provenance[key]);
    return provenance[key].is_string() ? text.substr(1, text.size() - 2) : text;
  };
  std::string header;
  header += "# dlpverify " + field("version") + " (commit " + field("git_commit") + ", " + field("build_type") + "): " +
            what + "\n";
  header += "# date " + field("date") + ", host " + field("host") + ", threads " + field("threads") + "\n";
  header += "# " + field("compiler") + ", SUNDIALS " + field("sundials") + ", Eigen " + field("eigen") + ", GSL " +
            field("gsl") + "\n";
  header += "# command: " + field("command_line") + "\n";
  header += "# options: " + json_text(options) + "\n";
  return header;
}

}  // namespace dlpverify
