// `whitted-pov-export SCENE -o OUT.pov`: writes a scene file as an equivalent
// POV-Ray 3.7 scene.
//
// Why: `make bench` times POV-Ray on the scene `whitted` renders; this small
// tool is also how a person checks the export by eye (render both, compare).
#include "output_size.hpp"
#include "pov_scene.hpp"
#include "whitted/scene_loader.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <fstream>
#include <optional>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{"whitted-pov-export: write an NFF or P3F scene as an equivalent POV-Ray 3.7 scene."};
    app.footer("Example: whitted-pov-export balls4.nff -o balls4.pov --width 512 --height 512\n"
               "then: povray +Iballs4.pov +Oballs4.png +W512 +H512 -A +WT2 -D +FN");
    std::string scene, output;
    std::optional<int> width, height, max_depth;
    bool filtered_shadows = false;
    app.add_option("scene", scene, "Scene file (.nff or .p3f)")->required();
    app.add_option("-o,--output", output, "The .pov file to write")->required();
    app.add_option("--width", width, "Image width in pixels (default: the scene file's)")->check(CLI::Range(1, 16384));
    app.add_option("--height", height, "Image height in pixels (default: the scene file's)")->check(CLI::Range(1, 16384));
    app.add_option("--max-depth", max_depth, "POV-Ray's max_trace_level; the eye ray is level 1 (default: the scene's)")
        ->check(CLI::Range(1, 100));
    app.add_flag("--filtered-shadows", filtered_shadows,
                 "Let POV-Ray shine light through transparent objects (whitted's shadows are opaque)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        std::fprintf(stderr, "whitted-pov-export: %s\n", error.what());
        return 2;
    }
    try {
        whitted::LoadedScene loaded = whitted::load_scene(scene);
        for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
        loaded.data.camera = whitted::bench::camera_at_size(loaded.data.camera, width, height);
        whitted::bench::PovOptions options;
        options.max_trace_level = max_depth.value_or(loaded.data.max_depth);
        options.opaque_shadows = !filtered_shadows;
        options.source = scene;
        std::ofstream out(output);
        if (!out) {
            std::fprintf(stderr, "whitted-pov-export: cannot write %s\n", output.c_str());
            return 1;
        }
        whitted::bench::write_pov_scene(loaded.data, options, out);
        out.close();
        if (!out) {
            std::fprintf(stderr, "whitted-pov-export: cannot write %s\n", output.c_str());
            return 1;
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
    return 0;
}
