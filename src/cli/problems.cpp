#include "cli/problems.hpp"

#include <variant>

#include "families/family.hpp"

namespace dlpverify::cli {

using families::Family;
using families::FamilyOption;
using families::families;

void add_problem_options(CLI::App& app, ProblemOptions& o) {
  for (const Family* family : families())
    for (const FamilyOption& option : family->options(o))
      std::visit(
          [&](auto* value) {
            CLI::Option* bound = app.add_option(option.name, *value, option.help)->group(option.group);
            if constexpr (!requires { value->has_value(); }) bound->capture_default_str();
          },
          option.value);
}

}  // namespace dlpverify::cli
