// sinsim fit DATA [options] -o MODEL.yaml: the identify pipeline (errormodels/identify.hpp) on a
// static record; writes an error-model file that `sinsim run --model` and `sinsim synth` read.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/record_options.hpp"
#include "cli/terminal.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/units.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::cli {
namespace {

struct FitArgs {
  std::string data, output;
  std::vector<std::string> axes;
  std::string kind = "auto", order = "auto", criterion = "mdl", denoise = "none";
  std::string denoise_rule = "universal", denoise_mode = "soft";
  int denoise_level = -1;
  bool ar_on_denoised = false;
  RecordArgs record;
  long long max_order = 20;
  std::string nav_step = "10 ms";
  std::string lines = "fit";
  bool quiet = false;
  unsigned threads = 0;
};

std::vector<std::string> splitAxes(const std::vector<std::string>& in) {
  std::vector<std::string> out;
  for (const auto& s : in) {
    std::string cur;
    for (char c : s + ",") {
      if (c == ',' || c == ' ') {
        if (!cur.empty()) out.push_back(cur);
        cur.clear();
      } else {
        cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      }
    }
  }
  return out;
}

void printSummary(const errormodels::Identification& id) {
  std::printf("fit: %s: %zu samples at %g Hz (%.1f s used)\n", id.source.c_str(), id.samples,
              id.rate_hz, id.duration());
  for (const auto& a : id.axes) {
    std::printf("  %s: %s", a.channel.c_str(), errormodels::toString(a.kind).c_str());
    if (a.written.ar)
      std::printf(", AR(%zu) gain %.4g", a.written.ar->order,
                  a.written.ar->drivingVariancePath.front() / a.written.ar->drivingVariance);
    if (a.written.allan) {
      for (std::size_t j = 0; j < errormodels::fit::kAllanTermCount; ++j) {
        const auto& t = a.written.allan->terms[j];
        if (a.written.allanWrite[j] && t.detected) std::printf(", %s", errormodels::fit::toString(t.kind).c_str());
      }
    }
    if (a.written.gaussMarkov)
      std::printf(", GM tau %.4g s", a.written.gaussMarkov->tau);
    if (a.arSlow) std::printf(", AR(%zu) + slow terms", a.arSlow->ar.fit.order);
    if (a.written.latent) {
      const auto& f = *a.written.latent;
      std::printf(": %s (chi2 %.3g / %zu dof, p %.2g", f.terms.name().c_str(), f.chi2, f.dof, f.pValue);
      if (const auto* r = f.runnerUp()) std::printf("; runner-up %s", r->terms.name().c_str());
      std::printf(")");
      for (const auto& g : f.model.gm) std::printf(", GM tau %.4g s", g.tau);
    }
    if (a.written.roundedRateLsb > 0.0) std::printf(", + quantization (each sample rounded onto the record's value lattice)");
    std::printf("\n");
  }
}

int runFit(const FitArgs& a) {
  // Every option is checked before the (possibly long) load.
  errormodels::IdentifyOptions opt;
  opt.kind = errormodels::identifyKindByName(a.kind);
  if (a.order != "auto") {
    std::size_t used = 0;
    long long p = -1;
    try {
      p = std::stoll(a.order, &used);
    } catch (const std::exception&) {
    }
    if (used != a.order.size() || p < 1 || p > limits::kMaxArOrder)
      throw InputError("--order: expected an integer from 1 to " +
                       std::to_string(limits::kMaxArOrder) + " or auto, got \"" +
                       limits::echo(a.order) + "\"");
    opt.order = static_cast<std::size_t>(p);
  }
  if (a.max_order < 1 || a.max_order > limits::kMaxArOrder)
    throw InputError("--max-order: expected an integer from 1 to " +
                     std::to_string(limits::kMaxArOrder) + " (docs/limits.md)");
  opt.maxOrder = std::max(static_cast<std::size_t>(a.max_order), opt.order.value_or(0));  // the table covers a forced order
  opt.criterion = errormodels::orderCriterionByName(a.criterion);
  if (a.denoise == "db5") opt.denoise = errormodels::DenoiseChoice::Db5;
  else if (a.denoise != "none")
    throw InputError("--denoise: expected db5 or none, got \"" + a.denoise + "\"");
  if (a.denoise_rule == "sure") opt.denoiseOptions.rule = errormodels::ThresholdRule::Sure;
  else if (a.denoise_rule != "universal")
    throw InputError("--denoise-rule: expected universal or sure, got \"" + a.denoise_rule + "\"");
  if (a.denoise_mode == "hard") opt.denoiseOptions.mode = errormodels::ThresholdMode::Hard;
  else if (a.denoise_mode != "soft")
    throw InputError("--denoise-mode: expected soft or hard, got \"" + a.denoise_mode + "\"");
  if (a.denoise_level != -1 && !(a.denoise_level >= 1 && a.denoise_level <= 30))
    throw InputError("--denoise-level: expected a level from 1 to 30");
  opt.denoiseOptions.level = a.denoise_level;
  opt.arOnDenoised = a.ar_on_denoised;
  opt.axes = splitAxes(a.axes);
  opt.navigationStep = parseOptionQuantity(a.nav_step, Dimension::time(), "--nav-step");
  opt.fitLines = errormodels::fitLinesByName(a.lines);
  if (opt.arOnDenoised && opt.denoise != errormodels::DenoiseChoice::Db5)
    throw InputError("--ar-on-denoised needs --denoise db5");
  if (opt.arOnDenoised && opt.kind != errormodels::IdentifyKind::Ar)
    throw InputError("--ar-on-denoised (the paper's literal pipeline) needs --kind ar");
  opt.threads = a.threads;

  // `--skip auto` (fit only): the record from its start; the fit skips a settling it finds.
  RecordArgs recordArgs = a.record;
  if (recordArgs.skip == "auto") {
    opt.skipAuto = true;
    recordArgs.skip.clear();
  }
  const errormodels::RecordOptions ro = recordOptions(recordArgs);
  const errormodels::Record rec = errormodels::loadRecord(a.data, ro);
  requireWritableTarget(a.output);  // before the fit, not after it

  const errormodels::Identification id = errormodels::identify(rec, opt);
  endProgressLine();
  for (const auto& w : id.warnings) std::fprintf(stderr, "fit: warning: %s\n", w.c_str());
  id.writeModel(a.output);  // temporary + rename: never half-written
  if (!a.quiet) printSummary(id);
  std::printf("fit: wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

void addFitCommand(CLI::App& app, Action& action) {
  auto a = std::make_shared<FitArgs>();
  CLI::App* c = app.add_subcommand(
      "fit", "fit an error model to a static record (ACF, Allan, Burg AR / GM / Allan terms) and "
             "write it as an error-model YAML file");
  c->add_option("DATA", a->data, "record: CSV or CSV.gz with header (t, gx gy gz, ax ay az, temp)")
      ->required();
  c->add_option("-o,--output", a->output, "model file to write (YAML)")->required();
  c->add_option("--axes", a->axes, "channels to fit, e.g. gx,gy,gz (default: all in the record)");
  c->add_option("--threads", a->threads, "worker threads over the channels (default: all cores)")
      ->check(CLI::Range(0u, sinsim::limits::kMaxThreads));
  c->add_option("--kind", a->kind, "ar | gm | allan | latent | ar+slow | auto (default auto: see README; gm, latent and ar+slow: docs/fitting.md)");
  c->add_option("--order", a->order, "AR order P or auto (default auto: by --criterion)");
  c->add_option("--criterion", a->criterion, "order criterion: mdl (default) | bic | aic | fpe | paper");
  c->add_option("--max-order", a->max_order, "largest AR order tried (default 20)");
  c->add_option("--nav-step", a->nav_step, "navigation step of the paper's order rule (default \"10 ms\")");
  c->add_option("--lines", a->lines,
                "narrow lines (a vibration): fit = written as sinusoids and taken out before the noise terms "
                "are fitted (default); warn = left in the record, with a warning");
  c->add_option("--denoise", a->denoise, "db5 | none (default none): db5 denoise before the ACF");
  c->add_option("--denoise-rule", a->denoise_rule, "universal (default) | sure");
  c->add_option("--denoise-mode", a->denoise_mode, "soft (default) | hard");
  c->add_option("--denoise-level", a->denoise_level, "decomposition level (default: largest)");
  c->add_flag("--ar-on-denoised", a->ar_on_denoised,
              "write the AR fitted on the denoised record (the paper's pipeline; too little white noise)");
  addRecordOptions(c, a->record);
  c->add_flag("-q,--quiet", a->quiet, "print only the output file name and the warnings (no per-channel summary)");
  c->callback([a, &action] { action = [a] { return runFit(*a); }; });
}

}  // namespace sinsim::cli
