#!/usr/bin/env python3
"""Resolve #include in the project's shaders, validate each with glslangValidator, and embed them.

Every .vert/.frag/.comp under --source is a shader entry point. `#include "path"` is resolved
relative to --source (each file is included once per shader; a cycle is an error) and replaced
by the file's text between `#line` directives, so driver messages point at the right file:
the second number of a `#line` is an index into the file table written beside the sources.

Outputs under --out:
  resolved/<name>         the resolved source, as the driver will see it (before runtime defines)
  embedded_shaders.cpp    the sources and file table as C++ string literals
  variants/<macro>/<name> the resolved source with a VARIANTS define set, validated too
  validated.stamp         touched after every shader passed glslangValidator
"""
import argparse
import pathlib
import re
import subprocess
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*$')
STAGES = (".vert", ".frag", ".comp")
# Runtime defines that switch a shader to code the build machine's GPU never compiles: a shader
# that names one is validated a second time with it set (the H200's driver refused a raster pass
# that used 64-bit atomics without enabling their extension; llvmpipe runs the other path).
VARIANTS = {"ML_RASTER_ATOMIC64": "1"}


class ShaderError(Exception):
    pass


def resolve(root, path, files, included, stack):
    rel = path.relative_to(root).as_posix()
    if rel in stack:
        raise ShaderError(f"{rel}: include cycle: {' -> '.join(stack + [rel])}")
    if rel not in files:
        files.append(rel)
    file_id = files.index(rel)
    out = []
    lines = path.read_text().splitlines()
    for number, line in enumerate(lines, start=1):
        m = INCLUDE.match(line)
        if not m:
            out.append(line)
            continue
        target = (root / m.group(1)).resolve()
        if not target.is_file():
            raise ShaderError(f"{rel}:{number}: included file not found: {m.group(1)}")
        target_rel = target.relative_to(root).as_posix()
        if target_rel in included:
            out.append(f"// (already included: {target_rel})")
            continue
        included.add(target_rel)
        if target_rel not in files:
            files.append(target_rel)
        out.append(f"#line 1 {files.index(target_rel)}")
        out.extend(resolve(root, target, files, included, stack + [rel]))
        out.append(f"#line {number + 1} {file_id}")
    return out


def cpp_literal(text):
    delimiter = "glsl"
    if f"){delimiter}\"" in text:
        raise ShaderError("shader text contains the raw-string delimiter")
    return f'R"{delimiter}({text}){delimiter}"'


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--source", required=True, type=pathlib.Path)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    parser.add_argument("--validator", default="glslangValidator")
    args = parser.parse_args()

    root = args.source.resolve()
    resolved_dir = args.out / "resolved"
    resolved_dir.mkdir(parents=True, exist_ok=True)

    files = []  # one file table for all shaders, so ids are stable within a build
    shaders = []
    for path in sorted(p for p in root.rglob("*") if p.suffix in STAGES):
        name = path.relative_to(root).as_posix()
        try:
            body = resolve(root, path, files, set(), [])
            # Runtime defines go right after #version; this #line keeps numbering true after them.
            body.insert(1, f"#line 2 {files.index(name)}")
            text = "\n".join(body) + "\n"
        except ShaderError as e:
            print(f"error: {e}", file=sys.stderr)
            return 1
        if not text.startswith("#version"):
            print(f"error: {name}: the first line must be #version", file=sys.stderr)
            return 1
        out_path = resolved_dir / name
        out_path.parent.mkdir(parents=True, exist_ok=True)
        out_path.write_text(text)
        shaders.append((name, text, out_path))

    failed = False
    for name, text, out_path in shaders:
        checks = [("", out_path)]
        for macro, value in VARIANTS.items():
            if macro not in text:
                continue
            # Set right after #version, as the program does at run time.
            variant_path = args.out / "variants" / macro / name
            variant_path.parent.mkdir(parents=True, exist_ok=True)
            first, _, rest = text.partition("\n")
            variant_path.write_text(f"{first}\n#define {macro} {value}\n{rest}")
            checks.append((f" with {macro} {value}", variant_path))
        for label, path in checks:
            result = subprocess.run([args.validator, str(path)], capture_output=True, text=True)
            if result.returncode != 0:
                failed = True
                message = (result.stdout + result.stderr).strip()
                print(f"error: {name}{label} failed glslangValidator:\n{message}\n(file ids: "
                      + ", ".join(f"{i}={f}" for i, f in enumerate(files)) + ")", file=sys.stderr)
    if failed:
        return 1

    lines = [
        "// Generated by tools/embed_shaders.py from glsl/. Do not edit.",
        '#include "renderer/gl/shader_sources.h"',
        "",
        "namespace ml::shaders {",
        "",
        "const std::vector<std::string_view>& fileTable() {",
        "    static const std::vector<std::string_view> table{",
    ]
    lines += [f'        "{f}",' for f in files]
    lines += ["    };", "    return table;", "}", "",
              "const std::vector<EmbeddedShader>& embedded() {",
              "    static const std::vector<EmbeddedShader> list{"]
    for name, text, _ in shaders:
        lines.append(f'        {{"{name}", {cpp_literal(text)}}},')
    lines += ["    };", "    return list;", "}", "", "}  // namespace ml::shaders", ""]
    (args.out / "embedded_shaders.cpp").write_text("\n".join(lines))
    (args.out / "validated.stamp").write_text("ok\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
