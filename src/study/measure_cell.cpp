// One cell, end to end: plan the taps, run the engine, and hand the taps to the tests. The χ² steps are tested
// as the engine taps them, and only the NIST steps' words are kept to the end of the run (the bulk of a cell's
// memory), dropped as soon as the battery has read them. A bilayer cell is its run alone.
#include "dpdrng/dpd/bilayer.hpp"
#include "dpdrng/dpd/water.hpp"
#include "dpdrng/rng/stream.hpp"
#include "dpdrng/study/measure.hpp"

namespace dpdrng::study {

CellResult measure_cell(const Cell& cell, const StudyConfig& config, int threads) {
  CellResult out;
  out.cell = cell;
  if (config.scene.is_bilayer()) {
    record_bilayer(dpd::run_bilayer(bilayer_engine_config(cell, config, threads)), out);
    return out;
  }
  const rng::GeneratorSpec spec = rng::validated(rng::GeneratorSpec{cell.generator, cell.rounds, rng::kPaperTeaKey});
  const int words = cell.reference ? 1 : rng::words_per_call(spec);
  const TapPlan plan = plan_taps(cell, config, words);
  Chi2Steps chi2(plan, config.tests);
  dpd::RunHooks hooks;
  hooks.raw = [&chi2](const dpd::RawTap& tap) { return chi2.take(tap); };
  dpd::RunResult run = dpd::run_water(engine_config(cell, config, threads, plan), hooks);
  record_run(run, out);
  // A blown-up run still has taps up to the blow-up; its tests would describe a broken trajectory, so the
  // cell keeps the observables up to that step and the reason, and skips the tests.
  if (out.status != CellStatus::ok) return out;
  if (!integrator_of(cell.integrator, config.scene).tapped()) {
    if (config.tests.chi2_steps > 0 || config.tests.ttest_pairs > 0)
      out.notes["tests"] = "not run: " + cell.integrator + " draws no numbers in the tapped pair loop";
    return out;
  }
  chi2.record(out);
  record_ttest(run.taps, config.tests, out);
  record_correlations(run.taps, config.tests, out);
  if (cell.nist) record_nist(run.taps, plan, config.tests, threads, out);
  return out;
}

}  // namespace dpdrng::study
