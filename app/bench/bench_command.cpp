#include "app/bench/bench_command.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "app/bench/bench_presets.h"
#include "app/bench/bench_progress.h"
#include "app/bench/bench_runner.h"
#include "app/bench/bench_sweep.h"
#include "app/bench/bench_table.h"
#include "app/bench/machine_info.h"
#include "app/offscreen_session.h"
#include "app/bench/stop_request.h"

namespace ml::app {

namespace {

struct BenchOptions {
    std::string preset;
    std::string sweepFile;
    std::vector<std::string> experiments;
    std::map<std::string, std::string> axes;  // axis key -> comma list, for the flags given
    std::map<std::string, CLI::Option*> axisFlags;
    std::optional<int> warmup, timedFrames;
    std::optional<long long> frame;
    std::optional<double> naiveBudget;
    std::string reference;
    std::string cameraPath;
    std::string outDir = "bench-results";
    std::string name;
    std::string backend = "auto";
    bool glDebug = false;
    bool listPresets = false;
    bool printSweep = false;
    bool dryRun = false;
};

std::string utcNow() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

nlohmann::json readSweepFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::invalid_argument("--sweep " + path + ": cannot open");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::invalid_argument("--sweep " + path + ": not valid JSON (" + std::string(e.what()) + ")");
    }
}

// The sweep the flags describe: a preset or a file, with the axis flags given laid over it.
Sweep sweepFromOptions(const BenchOptions& o, nlohmann::json& overrides) {
    if (!o.preset.empty() && !o.sweepFile.empty()) throw std::invalid_argument("--preset and --sweep: give one, not both");
    nlohmann::json doc;
    if (!o.preset.empty()) doc = benchPreset(o.preset);
    else if (!o.sweepFile.empty()) doc = readSweepFile(o.sweepFile);
    else doc = nlohmann::json{{"name", "sweep"}, {"description", "given by flags"}};
    overrides = nlohmann::json::object();
    for (const auto& [key, option] : o.axisFlags)
        if (option->count() > 0) overrides[key] = axisValuesFromFlag(key, o.axes.at(key));
    Sweep sweep = expandSweep(doc, overrides, o.experiments);
    if (o.warmup) {
        if (*o.warmup < 0 || *o.warmup > 1000) throw std::invalid_argument("--warmup: must be between 0 and 1000");
        sweep.run.warmupFrames = *o.warmup;
    }
    if (o.timedFrames) {
        if (*o.timedFrames < 1 || *o.timedFrames > 10000) throw std::invalid_argument("--timed-frames: must be between 1 and 10000");
        sweep.run.timedFrames = *o.timedFrames;
    }
    if (o.frame) {
        if (*o.frame < 0 || *o.frame > 100'000'000) throw std::invalid_argument("--frame: must be between 0 and 100000000");
        sweep.run.firstFrame = static_cast<std::uint32_t>(*o.frame);
    }
    if (o.naiveBudget) {
        if (!(*o.naiveBudget > 0.0)) throw std::invalid_argument("--naive-budget: must be > 0 (pixels x lights)");
        sweep.run.naiveBudget = *o.naiveBudget;
    }
    if (!o.reference.empty()) {
        try {
            applyReferenceSetting(sweep.run, o.reference);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--reference " + o.reference + ": " + e.what());
        }
    }
    if (!o.cameraPath.empty()) {
        for (const BenchPoint& p : sweep.points)
            if (!p.frame.camera.empty())
                throw std::invalid_argument("--camera-path " + o.cameraPath + " and camera " + p.frame.camera + " (" +
                                            p.experiment + "): give one of them");
        sweep.run.cameraPath = CameraPath::load(o.cameraPath);
    }
    return sweep;
}

nlohmann::ordered_json runJson(const RunSettings& run, const BenchRunner& runner) {
    nlohmann::ordered_json r;
    r["warmup_frames"] = run.warmupFrames;
    r["timed_frames"] = run.timedFrames;
    r["frame_index"] = run.firstFrame;
    r["naive_budget_pixel_lights"] = runner.naiveBudget();
    r["reference"] = referenceSettingName(run);
    if (run.cameraPath) r["camera_path"] = true;
    r["clock"] = timingClockName(runner.clock());
    return r;
}

int runBench(const BenchOptions& o) {
    if (o.listPresets) {
        for (const std::string& name : benchPresetNames())
            std::printf("%-8s %s\n", name.c_str(), benchPreset(name).value("description", "").c_str());
        return 0;
    }
    nlohmann::json overrides;
    const Sweep sweep = sweepFromOptions(o, overrides);
    if (o.printSweep) {
        std::printf("%s\n", sweep.document.dump(2).c_str());
        if (!overrides.empty()) std::printf("flags laid over every experiment: %s\n", overrides.dump().c_str());
        return 0;
    }
    if (o.dryRun) {
        for (std::size_t i = 0; i < sweep.points.size(); ++i)
            std::printf("%4zu  %s\n", i, describePoint(sweep.points[i]).c_str());
        std::printf("%zu points in %zu experiments\n", sweep.points.size(), sweep.experiments.size());
        return 0;
    }

    const std::string name = o.name.empty() ? sweep.name : o.name;
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) throw std::runtime_error(o.outDir + ": cannot create the output directory: " + ec.message());
    const std::string csvPath = (std::filesystem::path(o.outDir) / (name + ".csv")).string();
    const std::string jsonPath = (std::filesystem::path(o.outDir) / (name + ".json")).string();

    // One context for the whole sweep.
    FrameOptions contextOptions = sweep.points.front().frame;
    contextOptions.backend = o.backend;
    contextOptions.glDebug = o.glDebug;
    PreparedFrame shell;
    parseSize(contextOptions.size, shell.settings.width, shell.settings.height);
    shell.context.backend = parseBackend(o.backend);
    shell.context.debug = o.glDebug;
    OffscreenSession session = openOffscreen(contextOptions, shell);

    BenchRunner runner(sweep.run, session.info);
    nlohmann::ordered_json record;
    record["format"] = "manylights-bench-1";
    record["name"] = name;
    record["sweep"] = sweep.name;
    record["description"] = sweep.description;
    record["csv"] = std::filesystem::path(csvPath).filename().string();
    record["started_utc"] = utcNow();
    record["finished_utc"] = nullptr;
    record["status"] = "running";
    record["machine"] = describeMachine(session.info, session.context->platform());
    record["build"] = describeBuild();
    record["run"] = runJson(sweep.run, runner);
    nlohmann::ordered_json options;
    options["preset"] = o.preset.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(o.preset);
    options["sweep_file"] = o.sweepFile.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(o.sweepFile);
    options["experiments"] = o.experiments;
    options["overrides"] = overrides;
    options["backend"] = o.backend;
    record["options"] = options;
    record["experiments"] = sweep.experiments;
    record["sweep_document"] = sweep.document;

    std::fprintf(stderr, "manylights bench: %s, %zu points on %s (%s); writing %s\n", name.c_str(), sweep.points.size(),
                 session.info.renderer.c_str(), timingClockName(runner.clock()), csvPath.c_str());

    BenchTable table;
    StopRequest stop;
    BenchProgress progress(static_cast<int>(sweep.points.size()));
    auto save = [&](const char* status) {
        record["status"] = status;
        record["finished_utc"] = std::string(status) == "running" ? nlohmann::ordered_json() : nlohmann::ordered_json(utcNow());
        record["points"] = {{"planned", sweep.points.size()}, {"measured", table.rows().size()}, {"failed", runner.failed()}};
        record["columns"] = table.columns();
        record["passes"] = runner.passNames();
        record["rows"] = table.rowsJson();
        table.writeCsv(csvPath);
        writeFileAtomically(jsonPath, record.dump(1) + "\n");
    };
    bool interrupted = false;
    for (std::size_t i = 0; i < sweep.points.size(); ++i) {
        if (stop.requested()) {
            interrupted = true;
            break;
        }
        const BenchPoint& p = sweep.points[i];
        progress.starting(static_cast<int>(i), describePoint(p));
        BenchRow row = runner.measure(p, static_cast<int>(i));
        const std::string line = describePoint(p) + ": " + describeResult(row);
        table.add(std::move(row));
        save("running");  // after every point, so a crash or Ctrl-C loses at most the current one
        progress.finished(static_cast<int>(i), line);
    }
    interrupted = interrupted || stop.requested();
    progress.done();
    save(interrupted ? "interrupted" : "complete");
    std::fprintf(stderr, "wrote %s and %s (%zu of %zu points%s%s)\n", csvPath.c_str(), jsonPath.c_str(), table.rows().size(),
                 sweep.points.size(), interrupted ? ", interrupted" : "",
                 runner.failed() ? (", " + std::to_string(runner.failed()) + " failed: see the note column").c_str() : "");
    if (interrupted) return 130;
    return runner.failed() ? 1 : 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "sweep methods and settings; measure frame time, per-pass time, error against naive and cluster statistics");
    std::string presets;
    for (const std::string& n : benchPresetNames()) presets += (presets.empty() ? "" : ", ") + n;
    cmd->add_option("--preset", o->preset, "a sweep that ships with manylights: " + presets);
    cmd->add_option("--sweep", o->sweepFile, "a sweep file (JSON; see docs/bench/README.md and --print-sweep)");
    cmd->add_option("--experiment", o->experiments, "run only these experiments of the sweep")->delimiter(',');
    auto* axes = cmd->add_option_group("sweep axes", "comma-separated values; given with --preset/--sweep, they replace that axis in every experiment");
    for (const SweepAxis& a : sweepAxes()) {
        const std::string key = a.key;
        o->axisFlags[key] = axes->add_option(a.flag, o->axes[key], a.help);
    }
    auto* run = cmd->add_option_group("measurement");
    run->add_option("--warmup", o->warmup, "untimed frames before the timed ones (default: the sweep's, else 3)");
    run->add_option("--timed-frames", o->timedFrames, "timed frames per point, the lights animating (default: the sweep's, else 10)");
    run->add_option("--frame", o->frame, "animation frame of the first timed frame and of the accuracy frame (default: the sweep's, else 60)");
    run->add_option("--naive-budget", o->naiveBudget,
                    "pixels x lights a naive frame may cost, else naive and the accuracy columns are skipped (default " +
                        [] {
                            char buf[64];
                            std::snprintf(buf, sizeof buf, "%.0e on GPUs, %.0e on software renderers", kNaiveBudgetGpu,
                                          kNaiveBudgetSoftware);
                            return std::string(buf);
                        }() + ")");
    run->add_option("--reference", o->reference,
                    "naive (the accuracy columns); supersampled:K: also aa_rmse and aa_psnr_db against naive at K x K "
                    "samples per pixel, box-filtered; physical: also physical_* against naive with no cut-off (every light "
                    "reaching every pixel, pure inverse square, the point's BRDF) (default: the sweep's run.reference, else naive)");
    run->add_option("--camera-path", o->cameraPath,
                    "every point's timed frames follow this JSON camera path (the format of `render` and `view "
                    "--camera-path`); the first timed frame is the accuracy frame")
        ->check(CLI::ExistingFile);
    cmd->add_option("--out", o->outDir, "directory for <name>.csv and <name>.json")->capture_default_str();
    cmd->add_option("--name", o->name, "file name stem (default: the sweep's name)");
    cmd->add_option("--backend", o->backend, "offscreen GL: auto (EGL, then OSMesa), egl, osmesa")->capture_default_str();
    cmd->add_flag("--gl-debug", o->glDebug, "debug context; print every KHR_debug message");
    cmd->add_flag("--list-presets", o->listPresets, "list the presets and exit");
    cmd->add_flag("--print-sweep", o->printSweep, "print the sweep document (a starting point for --sweep) and exit");
    cmd->add_flag("--dry-run", o->dryRun, "list the points the sweep expands to and exit");
    cmd->callback([o, &exitCode] { exitCode = runBench(*o); });
}

}  // namespace ml::app
