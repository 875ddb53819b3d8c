#!/usr/bin/python3
"""Checks the README and the docs/ pages (issue 22): their commands run, their links lead
somewhere, and no page restates another page's table.

1. Commands. The README's first screen is everything before the first `## ` heading that follows
   the `## Two commands` heading (so the two commands, then the `### First commands` block).
   Every line of a fenced code block there that starts with `manylights ` (a trailing `\\`
   joins the next line; `# ...` comments are dropped) is run with the built binary in a fresh
   temporary directory, on Mesa llvmpipe, and must exit 0 and write what it names. To stay quick
   on two CPU cores the run differs from the printed line in these ways, and only these:
     - `render` and `bench` draw at 160x90 (`--size` replaced or added);
     - a frame range `A..B` is cut to `A..A+2` (three frames);
     - `bench` gets `--warmup 1 --timed-frames 1` unless the line sets them;
     - `view` runs under `xvfb-run` with a 320x180 window, `--frames 2` and a `--screenshot`
       (skipped, with a message, where xvfb-run is missing);
     - a line with `--video` is skipped, with a message, where ffmpeg is missing;
     - a `--scene FILE.glb`/`.gltf` that does not exist is written first: a small box on a floor
       (the stand-in for "a file of yours").
   tools/run and tools/test are not run (tools/test would run this test again).
   What each command writes is checked: PNGs decode at the size drawn and are not one flat
   colour; videos, CSVs and JSON files exist and are not empty; a bench CSV has a row per point.
2. Links. Every relative link and image in README.md and docs/*.md points to a file or folder
   that exists, and a `#anchor` to a heading of the target page (GitHub's heading slugs).
3. Paths. Every path of the tree that README.md or a docs/*.md page names (a word starting
   renderer/, app/, glsl/, scenes/, tests/, tools/ or docs/; `*` globs and `{h,cpp}` allowed)
   exists, so a page cannot keep pointing at a file that moved.
4. Tables. No table row of three or more cells (headers and separators aside) appears verbatim
   in two different files among README.md and docs/**/*.md: a table lives on one page and the
   others link to it.
"""
import argparse
import glob
import json
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import tempfile

SMALL_SIZE = "160x90"
VIEW_SIZE = "320x180"
FRAMES_KEPT = 3

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, flush=True)


# --- markdown helpers --------------------------------------------------------------------------

def strip_code(lines):
    """The lines with fenced code blocks blanked (links and headings there are not markdown)."""
    out, fenced = [], False
    for line in lines:
        if line.lstrip().startswith("```"):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else line)
    return out


def github_slug(heading):
    text = re.sub(r"`", "", heading.strip()).lower()
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's text, not its target
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors_of(path):
    slugs, seen = set(), {}
    for line in strip_code(open(path, encoding="utf-8").read().split("\n")):
        m = re.match(r"^(#{1,6}) +(.*?)#*\s*$", line)
        if not m:
            continue
        slug = github_slug(m.group(2))
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        slugs.add(slug if n == 0 else "%s-%d" % (slug, n))
    return slugs


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def check_links(root, pages):
    checked = 0
    for page in pages:
        text = "\n".join(strip_code(open(page, encoding="utf-8").read().split("\n")))
        text = re.sub(r"`[^`\n]*`", "", text)  # inline code is not a link
        for target in LINK.findall(text):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            checked += 1
            path, _, anchor = target.partition("#")
            where = os.path.relpath(page, root)
            resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(resolved):
                fail("%s: link to %s: no such file" % (where, target))
                continue
            if anchor and resolved.endswith(".md") and anchor not in anchors_of(resolved):
                fail("%s: link to %s: no heading with that anchor in %s"
                     % (where, target, os.path.relpath(resolved, root)))
    print("links: %d relative links checked in %d pages" % (checked, len(pages)))


# --- paths of the tree -----------------------------------------------------------------------

TREE_PATH = re.compile(r"(?<![\w./-])((?:renderer|app|glsl|scenes|tests|tools|docs)/[\w./*{},-]*)")


def check_paths(root, pages):
    checked = 0
    for page in pages:
        for number, line in enumerate(open(page, encoding="utf-8").read().split("\n"), 1):
            for match in TREE_PATH.finditer(line):
                path = match.group(1).rstrip(".,")
                braces = re.search(r"\{([^}]*)\}", path)
                names = [path[:braces.start()] + part + path[braces.end():] for part in braces.group(1).split(",")] \
                    if braces else [path]
                checked += 1
                if not all(glob.glob(os.path.join(root, name)) for name in names):
                    fail("%s:%d: %s does not exist" % (os.path.relpath(page, root), number, path))
    print("paths: %d paths of the tree checked" % checked)


# --- tables ---------------------------------------------------------------------------------------

def table_rows(path):
    lines = strip_code(open(path, encoding="utf-8").read().split("\n"))
    rows = []
    for i, line in enumerate(lines):
        s = line.strip()
        if not (s.startswith("|") and s.endswith("|")):
            continue
        cells = [c.strip() for c in s.strip("|").split("|")]
        if len(cells) < 3 or all(re.fullmatch(r":?-+:?", c) for c in cells):
            continue
        following = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if re.fullmatch(r"\|(\s*:?-+:?\s*\|)+", following):  # a header row
            continue
        rows.append(" | ".join(cells))
    return rows


def check_tables(root, pages):
    homes = {}
    for page in pages:
        for row in set(table_rows(page)):
            homes.setdefault(row, set()).add(os.path.relpath(page, root))
    repeated = {row: where for row, where in homes.items() if len(where) > 1}
    for row, where in sorted(repeated.items()):
        fail("table row in %s: | %s |" % (", ".join(sorted(where)), row[:120]))
    print("tables: %d distinct rows in %d pages, %d repeated" % (len(homes), len(pages), len(repeated)))


# --- the README's first commands ------------------------------------------------------------------

def first_screen_commands(readme):
    lines = open(readme, encoding="utf-8").read().split("\n")
    start = next((i for i, l in enumerate(lines) if l.startswith("## Two commands")), None)
    if start is None:
        fail("README.md has no '## Two commands' heading")
        return []
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    commands, fenced, pending = [], False, ""
    for line in lines[:end]:
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            continue
        line = pending + line.strip()
        pending = ""
        if line.endswith("\\"):
            pending = line[:-1] + " "
            continue
        if line.startswith("manylights "):
            commands.append(shlex.split(line, comments=True))
    return commands


def write_box_glb(path):
    """A floor and a box, positions, normals and indices, one grey material: a glTF of 'yours'."""
    positions, normals, indices = [], [], []

    def quad(corners, normal):
        base = len(positions)
        positions.extend(corners)
        normals.extend([normal] * 4)
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 3])

    quad([(-4, 0, 4), (4, 0, 4), (4, 0, -4), (-4, 0, -4)], (0, 1, 0))
    for axis in range(3):
        for sign in (-1, 1):
            normal = [0, 0, 0]
            normal[axis] = sign
            u, v = [a for a in range(3) if a != axis]
            corners = []
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sign, du, dv
                corners.append((p[0], p[1] + 1.0, p[2]))
            # wind counter-clockwise seen from outside
            a, b, c = corners[0], corners[1], corners[2]
            cross = [(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                     (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                     (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])]
            if sum(cross[i] * normal[i] for i in range(3)) < 0:
                corners.reverse()
            quad(corners, tuple(normal))
    pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
    idx_bytes = b"".join(struct.pack("<H", i) for i in indices)
    idx_bytes += b"\0" * (-len(idx_bytes) % 4)
    binary = pos_bytes + nrm_bytes + idx_bytes
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    doc = {
        "asset": {"version": "2.0", "generator": "tests/docs/check_docs.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                "metallicFactor": 0, "roughnessFactor": 0.5}}],
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos_bytes), "byteLength": len(nrm_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos_bytes) + len(nrm_bytes), "byteLength": 2 * len(indices),
             "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
    }
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(binary))
    glb += struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(binary), 0x004E4942) + binary
    with open(path, "wb") as f:
        f.write(glb)


def option(args, name):
    return args[args.index(name) + 1] if name in args and args.index(name) + 1 < len(args) else None


def set_option(args, name, value):
    if name in args:
        args[args.index(name) + 1] = value
    else:
        args += [name, value]


def frame_list(args):
    frames = option(args, "--frames")
    if frames is None:
        return [0]
    if ".." in frames:
        a, b = frames.split("..")
        return list(range(int(a), int(b) + 1))
    return [int(frames)]


def expand(pattern, frame):
    return re.sub(r"%(0?\d*)d", lambda m: ("%" + m.group(1) + "d") % frame, pattern).replace("%%", "%")


def check_png(path, size):
    from PIL import Image  # Debian's python3-pil, a dependency of python3-matplotlib
    with Image.open(path) as image:
        if "x".join(map(str, image.size)) != size:
            fail("%s is %dx%d, not %s" % (path, image.size[0], image.size[1], size))
        colours = image.convert("RGB").getcolors(maxcolors=1 << 16)
        if colours is not None and len(colours) < 16:
            fail("%s holds %d colours: an empty frame?" % (path, len(colours)))


def expect_file(path, what):
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        fail("%s: %s was not written" % (what, path))
        return False
    return True


def run_command(words, manylights, work, timeout):
    printed = " ".join(shlex.quote(w) for w in words)
    args = list(words[1:])
    sub = "render"  # manylights with no subcommand renders
    if args and not args[0].startswith("-"):
        sub = args.pop(0)
    if sub not in ("render", "view", "bench"):
        fail("README command with an unknown subcommand: " + printed)
        return
    if "--video" in args and shutil.which("ffmpeg") is None:
        print("skip (no ffmpeg): " + printed)
        return
    scene = option(args, "--scene")
    if scene and scene.endswith((".glb", ".gltf")) and not os.path.exists(os.path.join(work, scene)):
        write_box_glb(os.path.join(work, scene))
    frames = option(args, "--frames")
    if frames and ".." in frames:
        first = int(frames.split("..")[0])
        set_option(args, "--frames", "%d..%d" % (first, first + FRAMES_KEPT - 1))
    prefix = []
    if sub == "view":
        if shutil.which("xvfb-run") is None:
            print("skip (no xvfb-run): " + printed)
            return
        set_option(args, "--size", VIEW_SIZE)
        if "--frames" not in args:
            args += ["--frames", "2"]
        if "--screenshot" not in args:
            args += ["--screenshot", "view_check.png"]
        prefix = ["xvfb-run", "-a", "-s", "-screen 0 640x480x24"]
    else:
        set_option(args, "--size", SMALL_SIZE)
    if sub == "bench":
        if "--warmup" not in args:
            args += ["--warmup", "1"]
        if "--timed-frames" not in args:
            args += ["--timed-frames", "1"]
    run = prefix + [manylights, sub] + args
    print("run: " + printed + "\n  as: " + " ".join(shlex.quote(w) for w in run[len(prefix):]), flush=True)
    try:
        done = subprocess.run(run, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        fail("%s: no exit within %d s" % (printed, timeout))
        return
    if done.returncode != 0:
        fail("%s: exit %d\n%s" % (printed, done.returncode, done.stdout[-2000:]))
        return
    size = option(args, "--size")
    if sub == "render":
        out = option(args, "--out")
        sequence = len(frame_list(args)) > 1
        if out is None and not sequence:
            out = "manylights.png"
        if out is not None:
            for frame in frame_list(args) if "%" in out else [None]:
                path = os.path.join(work, expand(out, frame) if frame is not None else out)
                if expect_file(path, printed):
                    check_png(path, size)
        for flag in ("--video", "--timing-csv", "--out-float", "--save-lights", "--dump-clusters"):
            value = option(args, flag)
            if value is not None:
                for frame in frame_list(args) if "%" in value else [None]:
                    expect_file(os.path.join(work, expand(value, frame) if frame is not None else value), printed)
    elif sub == "view":
        for flag in ("--screenshot", "--screenshot-window"):
            value = option(args, flag)
            if value is not None and expect_file(os.path.join(work, value), printed) and flag == "--screenshot":
                check_png(os.path.join(work, value), size)
    else:
        directory = os.path.join(work, option(args, "--out") or "bench-results")
        stem = option(args, "--name") or "sweep"
        csv_path = os.path.join(directory, stem + ".csv")
        if expect_file(csv_path, printed) and expect_file(os.path.join(directory, stem + ".json"), printed):
            record = json.load(open(os.path.join(directory, stem + ".json")))
            rows = open(csv_path).read().strip().split("\n")[1:]
            if record.get("status") != "complete" or not rows:
                fail("%s: the bench record is %s with %d rows" % (printed, record.get("status"), len(rows)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", required=True, help="the repository root")
    parser.add_argument("--manylights", help="the built binary; without it the commands are not run")
    parser.add_argument("--work", help="a scratch directory (emptied first); default: a temporary one")
    parser.add_argument("--timeout", type=int, default=180, help="seconds one command may take")
    options = parser.parse_args()
    root = os.path.abspath(options.root)
    readme = os.path.join(root, "README.md")

    check_links(root, [readme] + sorted(glob.glob(os.path.join(root, "docs", "*.md"))))
    check_paths(root, [readme] + sorted(glob.glob(os.path.join(root, "docs", "*.md"))))
    check_tables(root, [readme] + sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True)))

    commands = first_screen_commands(readme)
    print("commands: %d in the README's first screen" % len(commands))
    if not commands:
        fail("no `manylights` command in the README's first screen")
    if options.manylights:
        os.environ.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
        os.environ.setdefault("GALLIUM_DRIVER", "llvmpipe")
        manylights = os.path.abspath(options.manylights)
        if options.work:
            shutil.rmtree(options.work, ignore_errors=True)
            os.makedirs(options.work)
            work = options.work
        else:
            work = tempfile.mkdtemp(prefix="ml-docs-")
        for words in commands:
            run_command(words, manylights, work, options.timeout)

    if failures:
        print("%d problem(s)" % len(failures))
        return 1
    print("docs: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
