"""Writes "constant answers" submissions: every lab function returns a constant.

    python3 instructor/scripts/lib/constant-labs.py OUT [--contract labs.hpp] [--variant NAME ...] [--list] [--switch]

Reads the lab contract (framework/include/whitted/labs.hpp: its "// ---- Lab N:
title (NN_name.cpp)" sections and the declarations under each) and writes
OUT/<variant>/NN_name.cpp for every variant, each lab file defining every
function of its section with one body that ignores what the function is for:

  nothing     the empty answer: std::nullopt, false, black, 0, the zero vector,
              no lights, a tree with no nodes, a ray from the origin along +z;
  something   a fixed answer that is not empty: a hit at t = 1 facing +z, true,
              white, 1, (0, 0, 1), (0.5, 0.5), one light, a tree of a single
              leaf holding every box (a valid hierarchy that never splits), a
              ray from the origin along -z;
  passthrough an input handed back where the function takes one of the type it
              returns (wo, u, t_range.min, the camera's eye, the light's centre,
              the ray unbent: -wo), else a third constant (grey, 0.5, a hit
              one unit along the ray, (1, 0, 0)).

None of them may score: instructor/scripts/test-hostile.sh grades them, and the
CTest proof `ctest -L constant` (instructor/tests/constants/CMakeLists.txt) runs
every lab's tests against each. For that proof, --switch writes instead
OUT/switch/NN_name.cpp, every variant in one file: each function answers the
variant that the environment variable WHITTED_CONSTANT names for the whole run
(one test program per lab rather than one per lab and variant). A contract function whose return type this
script does not know stops it with an error, so a new function cannot slip past
the proof: add its constants to CONSTANTS below.
"""
import argparse
import os
import re
import sys

VARIANTS = ("nothing", "something", "passthrough")

HIT_FACING_Z = "Hit{1.0, Point3(0.0), Vec3(0.0, 0.0, 1.0), Vec3(0.0, 0.0, 1.0), true, Vec2(0.0), 0, 0}"
ONE_LEAF = """[&] {
        BvhTree tree;
        if (boxes.empty()) return tree;
        Aabb all = boxes[0];
        for (const Aabb& box : boxes) all = Aabb{glm::min(all.min, box.min), glm::max(all.max, box.max)};
        tree.nodes.push_back(BvhNode{all, 0, static_cast<std::uint32_t>(boxes.size())});
        for (std::size_t i = 0; i < boxes.size(); ++i) tree.order.push_back(static_cast<std::uint32_t>(i));
        return tree;
    }()"""

# Return type -> (nothing, something, third constant). The third is the passthrough
# variant's answer for functions that take no input of the type they return.
CONSTANTS = {
    "Ray": ("Ray{Point3(0.0), Vec3(0.0, 0.0, 1.0)}", "Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}",
            "Ray{Point3(0.0, 0.0, 1.0), Vec3(0.0, 0.0, -1.0)}"),
    "std::optional<Hit>": ("std::nullopt", HIT_FACING_Z, "make_hit(ray, 1.0, -ray.direction)"),
    "bool": ("false", "true", "true"),
    "Color": ("Color(0.0)", "Color(1.0)", "Color(0.5)"),
    "Vec3": ("Vec3(0.0)", "Vec3(0.0, 0.0, 1.0)", "Vec3(1.0, 0.0, 0.0)"),
    "Point3": ("Point3(0.0)", "Point3(0.0, 0.0, 1.0)", "Point3(1.0, 0.0, 0.0)"),
    "Vec2": ("Vec2(0.0)", "Vec2(0.5)", "Vec2(0.25, 0.75)"),
    "double": ("0.0", "1.0", "0.5"),
    "std::optional<Vec3>": ("std::nullopt", "Vec3(0.0, 0.0, -1.0)", "Vec3(0.0, 0.0, 1.0)"),
    "std::optional<double>": ("std::nullopt", "1.0", "0.5"),
    "std::vector<PointLight>": ("std::vector<PointLight>{}", "std::vector<PointLight>{PointLight{Point3(0.0, 1.0, 0.0), Color(1.0)}}",
                                "std::vector<PointLight>{PointLight{Point3(0.0, 0.0, 1.0), Color(0.5)}}"),
    "BvhTree": ("BvhTree{}", ONE_LEAF, ONE_LEAF),
}

# Inputs handed back, by parameter type and name: (return type, parameter type, name) -> expression.
PASSTHROUGH = {
    ("Vec3", "const Vec3&", "wo"): "wo",                       # mirror_direction: the ray not turned
    ("std::optional<Vec3>", "const Vec3&", "wo"): "-wo",       # refracted_direction: the ray not bent
    ("double", "double", "cos_theta_i"): "cos_theta_i",        # fresnel_reflectance
    ("std::optional<double>", "Interval", "t_range"): "t_range.min",  # box_entry: always entered at once
    ("Vec2", "Vec2", "u"): "u",                                # stratified_sample, concentric_disk: u as it is
    ("Point3", "const AreaLight&", "light"): "light.center",   # point_on_light
    ("std::vector<PointLight>", "const AreaLight&", "light"): "std::vector<PointLight>{PointLight{light.center, light.color}}",
    ("Ray", "const Camera&", "camera"): "Ray{camera.eye, -camera.ze}",  # primary_ray, thin_lens_ray: straight ahead
    ("Ray", "const Hit&", "hit"): "Ray{hit.point, direction}",  # spawn_ray: no offset
}

SECTION = re.compile(r"^// ---- Lab (\d+): .* \((\d\d_[a-z0-9_]+)\.cpp\)")
DECLARATION = re.compile(r"^(?P<ret>[A-Za-z_:][\w:<>, ]*?)\s+(?P<name>\w+)\((?P<params>[^)]*)\);\s*$")


def parse_contract(path):
    """[(lab stem, [(return type, name, params text)])] in the contract's order."""
    labs = []
    for line in open(path, encoding="utf-8"):
        section = SECTION.match(line)
        if section:
            labs.append((section.group(2), []))
            continue
        declaration = DECLARATION.match(line)
        if declaration and labs:
            labs[-1][1].append((declaration.group("ret"), declaration.group("name"), declaration.group("params")))
    if not labs or not all(functions for _, functions in labs):
        sys.exit(f"constant-labs.py: {path}: no lab sections with declarations found")
    return labs


def split_params(params):
    """[(type, name)] of a parameter list (no default arguments or function types in the contract)."""
    result = []
    depth, start = 0, 0
    for i, c in enumerate(params + ","):
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
        elif c == "," and depth == 0:
            part = params[start:i].strip()
            start = i + 1
            if part:
                kind, name = part.rsplit(None, 1)
                result.append((kind, name))
    return result


def answer(ret, name, params, variant):
    if ret not in CONSTANTS:
        sys.exit(f"constant-labs.py: {name}() returns {ret}, which has no constants here: add them to CONSTANTS")
    nothing, something, third = CONSTANTS[ret]
    if variant == "nothing":
        return nothing
    if variant == "something":
        return something
    for kind, param in split_params(params):
        if (ret, kind, param) in PASSTHROUGH:
            return PASSTHROUGH[(ret, kind, param)]
    return third


# The --switch files: which variant WHITTED_CONSTANT names, read once.
CHOOSER = """namespace {

/// The variant WHITTED_CONSTANT names (%s), the same for the whole run.
int constant_variant() {
    static const int variant = [] {
        const char* name = std::getenv("WHITTED_CONSTANT");
        const char* const names[] = {%s};
        for (int i = 0; name && i < %d; ++i)
            if (std::strcmp(name, names[i]) == 0) return i;
        std::fprintf(stderr, "WHITTED_CONSTANT must name one of: %s\\n");
        std::abort();
    }();
    return variant;
}

} // namespace
""" % (", ".join(VARIANTS), ", ".join(f'"{v}"' for v in VARIANTS), len(VARIANTS), " ".join(VARIANTS))


def lab_file(stem, functions, variant):
    """The lab file of one variant, or of every variant chosen at run time when `variant` is None."""
    what = variant or "the variant WHITTED_CONSTANT names"
    lines = [f"// {stem}: every function answers the same whatever it is asked ({what}; made by",
             "// instructor/scripts/lib/constant-labs.py). It must score nothing.",
             '#include "whitted/labs.hpp"', "", "#include <cstdint>"]
    if variant is None:
        lines += ["#include <cstdio>", "#include <cstdlib>", "#include <cstring>"]
    lines += ["", "namespace whitted {", ""]
    if variant is None:
        lines += [CHOOSER]
    for ret, name, params in functions:
        names = [param for _, param in split_params(params)]
        lines.append(f"{ret} {name}({params}) {{")
        lines.append("    " + " ".join(f"(void){param};" for param in names))
        if variant is None:
            lines.append("    switch (constant_variant()) {")
            for i, each in enumerate(VARIANTS):
                label = f"case {i}" if i + 1 < len(VARIANTS) else "default"
                lines.append(f"    {label}: return {answer(ret, name, params, each)};")
            lines.append("    }")
        else:
            lines.append(f"    return {answer(ret, name, params, variant)};")
        lines.append("}")
        lines.append("")
    lines.append("} // namespace whitted")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", nargs="?", help="folder to write <variant>/NN_name.cpp into")
    parser.add_argument("--contract", default=os.path.join(os.path.dirname(__file__), "../../../framework/include/whitted/labs.hpp"))
    parser.add_argument("--variant", action="append", choices=VARIANTS, help="only these variants (default: all)")
    parser.add_argument("--list", action="store_true", help="print the variants and stop")
    parser.add_argument("--switch", action="store_true", help="write OUT/switch/: every variant in one file, WHITTED_CONSTANT chooses")
    args = parser.parse_args()
    if args.list:
        print("\n".join(VARIANTS))
        return
    if not args.out:
        parser.error("OUT is required")
    labs = parse_contract(args.contract)
    for variant in [None] if args.switch else args.variant or VARIANTS:
        folder = os.path.join(args.out, variant or "switch")
        os.makedirs(folder, exist_ok=True)
        for stem, functions in labs:
            text = lab_file(stem, functions, variant)
            path = os.path.join(folder, stem + ".cpp")
            # Unchanged files keep their time, so a build does not compile them again.
            if not os.path.exists(path) or open(path, encoding="utf-8").read() != text:
                with open(path, "w", encoding="utf-8") as file:
                    file.write(text)


if __name__ == "__main__":
    main()
