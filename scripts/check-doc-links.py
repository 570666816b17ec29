#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that documentation references resolve: every relative Markdown link and image in a
tracked *.md file, and every path under docs/ named in a tracked text file (guides, scripts,
sources, CMake, plugin XML, examples). A path after an output option (--csv, --plot, --plots,
--out, -o, >) need only have its directory. Recorded run outputs (docs/measurements/**/*.txt,
*.csv) and fuzz corpora are not read: they quote what a run printed.
  scripts/check-doc-links.py            (from anywhere in the repository; exit 1 on a broken one)
"""
import glob
import os
import re
import subprocess
import sys

root = subprocess.check_output(["git", "rev-parse", "--show-toplevel"], text=True).strip()
os.chdir(root)
files = subprocess.check_output(["git", "ls-files"], text=True).split("\n")
text_ext = (".md", ".sh", ".py", ".cxx", ".h", ".txt", ".cmake", ".in", ".xml", ".glsl", ".pvsm")
skip = re.compile(r"^(fuzz/corpus/|scripts/check-doc-links\.py$|docs/measurements/.*\.(txt|csv)$)")
link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
docs_path = re.compile(r"(?<![\w/.-])(?:\.\./)?(docs/[\w./{},*$-]*[\w*}])")
output_option = re.compile(r"(--csv|--plots?|--out|--photos|-o|>)\s*(\.\./)?$")


def expand(path):
    """Brace alternatives {a,b} as separate paths."""
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    return [p for alt in m.group(1).split(",")
            for p in expand(path[:m.start()] + alt + path[m.end():])]


def exists(path):
    return any(glob.glob(p) for p in expand(path)) if ("*" in path or "{" in path) \
        else os.path.exists(path)


broken, checked = [], 0
for f in files:
    if not f.endswith(text_ext) or skip.match(f) or not os.path.isfile(f):
        continue
    try:
        text = open(f, encoding="utf-8").read()
    except UnicodeDecodeError:
        continue
    for n, line in enumerate(text.split("\n"), 1):
        if f.endswith(".md"):
            for target in link.findall(line):
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue
                checked += 1
                path = os.path.normpath(os.path.join(os.path.dirname(f), target.split("#")[0]))
                if not exists(path):
                    broken.append(f"{f}:{n}: link {target}")
        for m in docs_path.finditer(line):
            path = m.group(1).rstrip(".")
            if "$" in path:
                path = path[:path.index("$")] + "*"
            checked += 1
            if exists(path):
                continue
            if output_option.search(line[:m.start()]) and os.path.isdir(os.path.dirname(path)):
                continue  # an output a command writes: its directory is enough
            broken.append(f"{f}:{n}: path {path}")
for b in broken:
    print(b)
print(f"{checked} references checked, {len(broken)} broken")
sys.exit(1 if broken else 0)
