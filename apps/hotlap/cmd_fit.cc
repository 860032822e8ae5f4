// `hotlap fit tyre|contact-length|brake`: thermal, wear, contact-length and brake parameters
// fitted to a telemetry log, with their uncertainty, written as a car (docs/fitting.md).

#include <chrono>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "fit_output.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/ident/contact_length_fit.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/synth_params.h"
#include "output.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;
using ident::FitParameter;
using ident::ParameterEstimate;

enum class FitKind { kTyre, kContactLength, kBrake };

struct FitArgs {
  std::string telemetry, car = "gen7", corners = "all", out, report, json, truth;
  std::string loss = "huber", initial_state = "fitted";
  double loss_scale = 3.0, sensor_lag_s = 0.0, max_relative_ci = 0.05, max_step_s = 0.02;
  int starts = 6, threads = 0;
  uint64_t seed = 1;
  std::optional<double> ambient_C, track_C;
  std::string wear_per_lap;  // tyre only
  double wear_sd_mm = 0.002;
  std::optional<int> laps;
};

const char* CommandName(FitKind kind) {
  switch (kind) {
    case FitKind::kTyre:
      return "fit tyre";
    case FitKind::kContactLength:
      return "fit contact-length";
    case FitKind::kBrake:
      break;
  }
  return "fit brake";
}

// Runs body(i) for every i < count on up to `threads` threads; rethrows the first error.
template <class F>
void ParallelFor(size_t count, int threads, F&& body) {
  const size_t n = std::min<size_t>(count, std::max(1, threads));
  std::vector<std::exception_ptr> errors(count);
  std::vector<std::thread> pool;
  for (size_t t = 0; t < n; ++t) {
    pool.emplace_back([&, t] {
      for (size_t i = t; i < count; i += n) {
        try {
          body(i);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      }
    });
  }
  for (std::thread& th : pool) th.join();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

std::string SourceComment(const std::string& date, const std::string& log, const FitParameter& p,
                          const ParameterEstimate& e) {
  std::string verdict;
  if (e.undetermined) {
    return fmt::format("fitted {} to {}: undetermined by the data (kept where the fit left it)",
                       date, log);
  }
  if (e.at_bound) verdict = "; at its bound";
  if (!e.well_determined && !e.at_bound) verdict = "; not well determined";
  return fmt::format("fitted {} to {}: std error {:.3g}, 95% [{:.5g}, {:.5g}]{}", date, log,
                     e.std_error, e.ci_low, e.ci_high, verdict);
}

// File edits for the model parameters of `fit`, keys prefixed with `section`.
std::vector<ident::FileEdit> EditsOf(const ident::FitResult& fit, const std::string& section,
                                     const std::string& date, const std::string& log) {
  std::vector<ident::FileEdit> edits;
  for (size_t i = 0; i < fit.parameters.size(); ++i) {
    const FitParameter& p = fit.parameters[i];
    if (p.role != ident::ParameterRole::kModel) continue;
    edits.push_back(
        {section + p.key, fit.estimates[i].value, SourceComment(date, log, p, fit.estimates[i])});
  }
  return edits;
}

ChannelPair Pair(std::string quantity, std::string title, std::string unit, std::string column_unit,
                 const std::vector<double>& measured, const std::vector<double>& model,
                 double scale, double offset) {
  ChannelPair p{std::move(quantity),    std::move(title), std::move(unit),
                std::move(column_unit), measured,         model};
  for (double& v : p.measured) v = v * scale + offset;
  for (double& v : p.model) v = v * scale + offset;
  return p;
}

std::array<double, 6> PEntries(const brake::ConvectionPolynomial<double>& l) {
  return {l.l11 * l.l11,
          l.l21 * l.l11,
          l.l21 * l.l21 + l.l22 * l.l22,
          l.l31 * l.l11,
          l.l31 * l.l21 + l.l32 * l.l22,
          l.l31 * l.l31 + l.l32 * l.l32 + l.l33 * l.l33};
}

// The true values (display units) of a corner's fitted parameters, by key.
std::map<std::string, double> TruthOf(const vehicle::Car& truth, Corner c) {
  const tyre::TyreThermalParams<double>& t = truth.tyre(c).params;
  const brake::BrakeThermalParams<double>& b = truth.brake(c).params;
  std::map<std::string, double> out = {{"p1", t.p1},
                                       {"p2_J_per_kgN", t.p2},
                                       {"p3_J_per_kgN", t.p3},
                                       {"p4_J_per_kgN", t.p4},
                                       {"p5_W_per_m2K", t.p5},
                                       {"wp1_mm_per_s", t.wear_coeff},
                                       {"wp2", t.wear_exponent},
                                       {"p_cp1", t.contact_length_coeff},
                                       {"p_cp2", t.contact_length_exponent},
                                       {"heat_partition", b.heat_partition},
                                       {"mass_participation", b.mass_participation}};
  constexpr std::array<const char*, 6> kP = {"P11", "P21", "P22", "P31", "P32", "P33"};
  const auto pd = PEntries(b.disc_convection), pk = PEntries(b.calliper_convection);
  for (int e = 0; e < 6; ++e) {
    out[fmt::format("disc_convection_{}_W_per_K", kP[e])] = pd[e];
    out[fmt::format("calliper_convection_{}_W_per_K", kP[e])] = pk[e];
  }
  return out;
}

int RunFit(const FitArgs& a, FitKind kind) {
  CheckOutputFolder(a.out, "--out");
  if (const std::string ext = fs::path(a.out).extension().string();
      ext != ".yaml" && ext != ".yml") {
    throw InputError(fmt::format("--out '{}': the fitted car is a .yaml file", a.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) {
    // A folder, created if it is not there; its parent must exist.
    const fs::path dir = fs::path(a.report).lexically_normal();
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    if (!fs::is_directory(parent) || (fs::exists(dir) && !fs::is_directory(dir))) {
      throw InputError(fmt::format(
          "--report '{}': must be a folder (created if missing) inside an existing one", a.report));
    }
  }
  const auto started = std::chrono::steady_clock::now();

  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car));
  const Telemetry log = Telemetry::Read(a.telemetry);
  const std::vector<Corner> corners = ident::ParseCornerList(a.corners, "--corners");
  std::optional<vehicle::Car> truth;
  if (!a.truth.empty()) {
    truth = car;
    sim::ApplyParameterOverrides(sim::LoadParameterOverrides(a.truth), *truth);
  }
  ident::LogFitOptions options;
  options.solver.loss = ident::ParseLossKind(a.loss);
  options.solver.loss_scale = a.loss_scale;
  options.solver.max_relative_ci = a.max_relative_ci;
  options.max_step_s = a.max_step_s;
  options.sensor_lag_s = a.sensor_lag_s;
  options.initial_state = ident::ParseInitialStateMode(a.initial_state);
  options.random_starts = a.starts;
  options.seed = a.seed;
  // The joint intervals hold every model parameter this command can fit, over all its corners:
  // p1..p5, wp1, wp2 per tyre; gamma, xi and the 12 convection entries per brake; p_cp1, p_cp2.
  const size_t per_corner = kind == FitKind::kTyre    ? ident::TyreParameterKeys().size()
                            : kind == FitKind::kBrake ? ident::BrakeParameterKeys().size()
                                                      : 2;
  options.solver.joint_family_size = static_cast<int>(corners.size() * per_corner);

  FitRun run;
  run.command = CommandName(kind);
  run.telemetry = a.telemetry;
  run.car_name = car.name;
  run.car_path = car.path.string();
  run.out = a.out;
  run.time = log.Channel("time");
  run.log_metadata = log.metadata();
  run.options = {{"loss", a.loss},
                 {"loss_scale", a.loss_scale},
                 {"max_relative_ci", a.max_relative_ci},
                 {"sensor_lag_s", a.sensor_lag_s},
                 {"initial_state", a.initial_state},
                 {"random_starts", a.starts},
                 {"seed", a.seed}};
  run.corners.resize(corners.size());
  run.joint_family_size = options.solver.joint_family_size;
  ident::FittedCarEdits edits;
  const std::string date = ident::TodayIsoDate();
  const std::string log_name = fs::path(a.telemetry).filename().string();
  edits.header = {fmt::format("Fitted by hotlap {} {} on {} to {}.", HOTLAP_VERSION, run.command,
                              date, fs::absolute(a.telemetry).lexically_normal().string()),
                  "Fitted values carry their own source comments; all others are as in the file "
                  "named below."};

  sim::InitialTemperatureOverrides overrides;
  if (a.ambient_C) overrides.ambient_temp = CelsiusToKelvin(*a.ambient_C);
  if (a.track_C) overrides.track_temp = CelsiusToKelvin(*a.track_C);
  std::optional<sim::ReplayInputs> inputs;
  std::vector<double> weights;
  if (kind != FitKind::kContactLength) {
    inputs = sim::ReplayInputsFromTelemetry(log, overrides);
    weights = ident::TrapezoidWeights(inputs->time);
  }
  const std::map<Corner, double> wear_per_lap =
      ident::ParseCornerValues(a.wear_per_lap, "--wear-per-lap-mm");
  const int laps = a.laps.value_or(ident::MetadataInt(log, "laps").value_or(1));
  const int threads =
      a.threads > 0 ? a.threads : static_cast<int>(std::thread::hardware_concurrency());

  ParallelFor(corners.size(), threads, [&](size_t n) {
    const Corner c = corners[n];
    const int i = CornerIndex(c);
    CornerOutcome& out = run.corners[n];
    out.corner = c;
    if (truth) out.truth = TruthOf(*truth, c);
    if (kind == FitKind::kTyre) {
      ident::TyreCornerData d;
      d.samples = ident::CornerSamplesOf(*inputs, c);
      d.tread = ident::ReadLoggedChannel(log, "tread_temp", c, 223.15, 573.15, 0.01);
      d.carcass = ident::ReadLoggedChannel(log, "carcass_temp", c, 223.15, 573.15, 0.01);
      d.wear = ident::ReadLoggedChannel(log, "wear", c, -1.0, 50.0, 1e-9);
      d.weights = weights;
      d.fallback_tread_temp = car.initial.tread_temp;
      d.fallback_carcass_temp = car.initial.carcass_temp;
      if (auto it = wear_per_lap.find(c); it != wear_per_lap.end()) {
        d.wear_total_mm = it->second * laps;
        d.wear_total_sd_mm = a.wear_sd_mm * laps;
      }
      const ident::TyreFitResult r = ident::FitTyreCorner(car.tyres[i], d, options);
      out.warnings = r.warnings;
      std::vector<std::string> fitted_keys;
      if (r.thermal) {
        out.fits.push_back({"thermal", *r.thermal, {}});
        out.rms = {{"rms_tread_C", r.thermal->channels[0].rms},
                   {"rms_carcass_C", r.thermal->channels[1].rms}};
        const auto e = EditsOf(*r.thermal, "heat_generation.", date, log_name);
        edits.tyres[i].insert(edits.tyres[i].end(), e.begin(), e.end());
      }
      if (r.wear) {
        out.fits.push_back({"wear", *r.wear, {}});
        out.rms.emplace_back("rms_wear_mm", r.wear->channels[0].rms);
        const auto e = EditsOf(*r.wear, "wear.", date, log_name);
        edits.tyres[i].insert(edits.tyres[i].end(), e.begin(), e.end());
      }
      for (const auto& f : out.fits) {
        for (const FitParameter& p : f.fit.parameters) fitted_keys.push_back(p.key);
      }
      const tyre::TyreThermalParams<double>& p = car.tyres[i].params;
      const std::vector<double> values = {p.p1, p.p2,         p.p3,           p.p4,
                                          p.p5, p.wear_coeff, p.wear_exponent};
      for (size_t k = 0; k < values.size(); ++k) {
        const std::string& key = ident::TyreParameterKeys()[k];
        if (std::find(fitted_keys.begin(), fitted_keys.end(), key) != fitted_keys.end()) continue;
        if (out.fits.empty()) break;
        out.fits.back().held[key] = values[k];
      }
      out.fitted = !out.fits.empty();
      out.channels = {Pair("tread_temp", "tread temperature", "\u00b0C", "C", d.tread.values,
                           r.tread_model, 1.0, -kZeroCelsius),
                      Pair("carcass_temp", "carcass temperature", "\u00b0C", "C", d.carcass.values,
                           r.carcass_model, 1.0, -kZeroCelsius),
                      Pair("wear", "wear", "mm", "mm", d.wear.values, r.wear_model, 1.0, 0.0)};
    } else if (kind == FitKind::kBrake) {
      ident::BrakeCornerData d;
      d.samples = ident::CornerSamplesOf(*inputs, c);
      d.disc = ident::ReadLoggedChannel(log, "disc_temp", c, 223.15, 1773.15, 0.01);
      d.calliper = ident::ReadLoggedChannel(log, "calliper_temp", c, 223.15, 1773.15, 0.01);
      d.weights = weights;
      d.fallback_disc_temp = car.initial.disc_temp;
      d.fallback_calliper_temp = car.initial.calliper_temp;
      const ident::BrakeFitResult r = ident::FitBrakeCorner(car.brakes[i], d, options);
      out.warnings = r.warnings;
      if (r.fit) {
        out.fits.push_back({"brake", *r.fit, {}});
        out.rms = {{"rms_disc_C", r.fit->channels[0].rms},
                   {"rms_calliper_C", r.fit->channels[1].rms}};
        // gamma and xi as reported; L as solved (its uncertainty is reported for P = L L').
        for (const ident::FileEdit& e : EditsOf(*r.fit, "", date, log_name)) {
          if (e.key == "heat_partition" || e.key == "mass_participation") {
            edits.brakes[i].push_back(e);
          }
        }
        for (const ident::FileEdit& e : EditsOf(*r.cholesky_fit, "", date, log_name)) {
          if (e.key.find("cholesky") == std::string::npos) continue;
          edits.brakes[i].push_back(
              {e.key, e.value,
               fmt::format("fitted {} to {}; its uncertainty is reported for P = L L' (fit "
                           "report)",
                           date, log_name)});
        }
        out.fitted = true;
      }
      out.channels = {Pair("disc_temp", "disc temperature", "\u00b0C", "C", d.disc.values,
                           r.disc_model, 1.0, -kZeroCelsius),
                      Pair("calliper_temp", "calliper temperature", "\u00b0C", "C",
                           d.calliper.values, r.calliper_model, 1.0, -kZeroCelsius)};
    } else {
      const std::vector<double> fz = log.FilledChannel("fz", c);
      const ident::LoggedChannel radius =
          ident::ReadLoggedChannel(log, "rolling_radius", c, 0.05, 2.0, 1e-7);
      const ident::ContactLengthFitResult r =
          ident::FitContactLength(car.tyres[i], fz, radius, options.solver);
      out.warnings = r.warnings;
      if (r.fit) {
        out.fits.push_back({"contact length", *r.fit, {}});
        out.rms = {{"rms_rolling_radius_mm", 1e3 * r.fit->channels[0].rms}};
        edits.tyres[i] = EditsOf(*r.fit, "contact_length.", date, log_name);
        out.fitted = true;
      }
      out.channels = {Pair("rolling_radius", "rolling radius", "mm", "mm", radius.values,
                           r.radius_model, 1e3, 0.0)};
    }
  });

  ident::WriteFittedCar(car, a.out, edits);
  run.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  PrintFitRun(run);
  fmt::print("wrote {} (and the folder {})\n", a.out,
             (fs::path(a.out).parent_path() / fs::path(a.out).stem()).string());
  if (!a.json.empty()) {
    WriteJsonFile(a.json, FitRunJson(run));
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    for (const fs::path& p : WriteFitReport(run, a.report)) fmt::print("wrote {}\n", p.string());
  }
  return 0;
}

void AddCommonOptions(CLI::App* sub, FitArgs& a) {
  sub->add_option("--telemetry", a.telemetry, "Logged channels (CSV, docs/telemetry-csv.md)")
      ->required();
  sub->add_option("--car", a.car, "Built-in car name or path to a car.yaml (the starting values)")
      ->capture_default_str();
  sub->add_option("--corners", a.corners, "Corners to fit: all, or a list such as fl,rr")
      ->capture_default_str();
  sub->add_option("--out", a.out, "The fitted car (.yaml; its parts go in a folder beside it)")
      ->required();
  sub->add_option("--report", a.report, "Folder for the HTML report and the channels CSV");
  sub->add_option("--json", a.json, "Write the results as JSON (docs/json-output.md)");
  sub->add_option("--truth", a.truth,
                  "Parameter file with the true values (hotlap synth --params), for the report");
  sub->add_option("--loss", a.loss, "Robust loss: huber, cauchy or none")->capture_default_str();
  sub->add_option("--loss-scale", a.loss_scale, "Where the loss starts, in noise levels")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--max-relative-ci", a.max_relative_ci,
                  "Well determined: 95% half-width at most this fraction of the value")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--starts", a.starts, "Seeded random starting points besides the guesses")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--seed", a.seed, "Seed of the random starts")->capture_default_str();
  sub->add_option("--threads", a.threads, "Corners fitted at once (0: one per core)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

void AddThermalOptions(CLI::App* sub, FitArgs& a) {
  sub->add_option("--sensor-lag-s", a.sensor_lag_s,
                  "First-order lag of the temperature sensors, modelled in the fit")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--initial-state", a.initial_state,
                  "fitted (initial temperatures fitted too) or measured (first samples)")
      ->capture_default_str();
  sub->add_option("--max-step-s", a.max_step_s, "Longest RK4 sub-step, s")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--ambient-temp-C", a.ambient_C, "Air temperature if not logged");
  sub->add_option("--track-temp-C", a.track_C, "Track temperature if not logged");
}

}  // namespace

CommandRunner RegisterFitCommand(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* fit = app.add_subcommand(
      "fit", "Fit thermal, wear, contact-length or brake parameters to a log, with uncertainty");
  fit->require_subcommand(1);
  CLI::App* tyre = fit->add_subcommand(
      "tyre", "Fit p1..p5 to tread and carcass temperatures, then wp1, wp2 to the wear");
  AddCommonOptions(tyre, *args);
  AddThermalOptions(tyre, *args);
  tyre->add_option("--wear-per-lap-mm", args->wear_per_lap,
                   "Measured wear per lap, e.g. fl=0.02,rr=0.033 (else a wear channel is used)");
  tyre->add_option("--wear-sd-mm", args->wear_sd_mm,
                   "Standard deviation of a --wear-per-lap-mm value, mm per lap")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  tyre->add_option("--laps", args->laps,
                   "Laps in the log, for --wear-per-lap-mm (default: the log's '# laps:', else 1)")
      ->check(CLI::PositiveNumber);
  CLI::App* contact = fit->add_subcommand(
      "contact-length", "Fit p_cp1, p_cp2 of the contact length to measured rolling radii");
  AddCommonOptions(contact, *args);
  CLI::App* brake = fit->add_subcommand(
      "brake", "Fit gamma, xi and the convection entries to disc and calliper temperatures");
  AddCommonOptions(brake, *args);
  AddThermalOptions(brake, *args);
  return [args, tyre, contact] {
    const FitKind kind = tyre->parsed()      ? FitKind::kTyre
                         : contact->parsed() ? FitKind::kContactLength
                                             : FitKind::kBrake;
    return RunFit(*args, kind);
  };
}

}  // namespace hotlap::app
