// manylights: renders a scene lit by thousands to millions of point lights by naive forward,
// clustered forward and clustered deferred shading, and measures what each costs.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/bench/bench_command.h"
#include "app/compare/compare_command.h"
#include "app/crash_report.h"
#include "app/info/info_command.h"
#include "app/bench/raster_floors_command.h"
#include "app/render/render_command.h"
#include "app/view/view_command.h"

int main(int argc, char** argv) {
    ml::app::installCrashReport();
    CLI::App app{"manylights: many-light rendering by naive, clustered forward and clustered deferred shading"};
    app.require_subcommand(0, 1);
    int exitCode = 0;
    ml::app::addRenderCommand(app, exitCode);
    ml::app::addBenchCommand(app, exitCode);
    ml::app::addViewCommand(app, exitCode);
    ml::app::addRasterFloorsCommand(app, exitCode);
    ml::app::addInfoCommand(app, exitCode);
    ml::app::addCompareCommand(app, exitCode);
    try {
        app.parse(argc, argv);
        // With no subcommand, do the main job: render the default scene.
        if (app.get_subcommands().empty()) {
            const char* defaultArgs[] = {argv[0], "render"};
            app.parse(2, const_cast<char**>(defaultArgs));
        }
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "manylights: error: %s\n", e.what());
        return 1;
    }
    return exitCode;
}
