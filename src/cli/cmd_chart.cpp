// dpdrng chart DIR: draws every chart under DIR again from the CSV and gnuplot script committed beside it, so a
// chart can be restyled or checked without the study's cells.
#include <iostream>
#include <memory>
#include <string>

#include "dpdrng/cli/registry.hpp"
#include "dpdrng/study/report.hpp"

namespace dpdrng::cli {
namespace cmd_chart {
namespace {

const bool registered = register_command(64, [](CLI::App& root) {
  auto dir = std::make_shared<std::string>();
  CLI::App* sub = root.add_subcommand("chart", "redraw every chart under DIR from its committed CSV and gnuplot script");
  sub->add_option("dir", *dir, "a directory holding charts (NAME.csv beside NAME.gp), e.g. results/okada2021/report")
      ->required();
  sub->footer("Each chart is NAME.csv (the numbers, one block per series), NAME.gp (the gnuplot script reading it)\n"
              "and NAME.svg / NAME.png (drawn by gnuplot). Edit a script and rerun to restyle a chart.\n"
              "The rules every chart follows: docs/charts.md.");
  sub->callback([dir] {
    begin_work();
    const std::size_t n = study::redraw_charts(*dir, &std::cerr);
    std::cout << n << " charts drawn under " << *dir << "\n";
  });
});

}  // namespace
}  // namespace cmd_chart
}  // namespace dpdrng::cli
