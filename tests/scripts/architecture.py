#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks that doc/architecture.md is true of the code (run by ctest as
scripts/architecture):

1. every file under include/rsfcycle/ and source/ lies in exactly one layer
   of the doc's table "Layers";
2. every #include <rsfcycle/...> runs downward or within its layer: a file
   includes no file of a higher layer;
3. every file is named in the doc (its path without extension, in
   backticks, e.g. `output/writer.h` or `output/writer.*`), and every file
   the doc names in backticks exists;
4. no file is longer than 600 lines;
5. no function body (the lines between its braces) is longer than 80
   lines, but the `declare_parameters` functions (one declare_entry after
   another) and those that the doc's section "Functions longer than 80
   lines" names, each as a bullet "- `Class::function` (N lines): why"
   ("- `Class` constructor (N lines)" for a constructor) with N the lines
   this script counts; a bullet for a function that is not longer is out
   of date.

Prints one line per violation and exits with 1 if there is one.
Usage: architecture.py REPOSITORY_ROOT
"""
import glob
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
doc_path = os.path.join(root, "doc", "architecture.md")
doc = open(doc_path).read()

# The layer table: rows "| N name | `a/`, `b.h`, `c.*` |" below "## Layers".
layers = []  # (number, name, [patterns])
section = doc.split("## Layers", 1)[1].split("\n## ", 1)[0]
for line in section.splitlines():
    m = re.match(r"^\|\s*(\d+)\s+([\w-]+)\s*\|(.*)\|\s*$", line)
    if m:
        layers.append((int(m.group(1)), m.group(2),
                       re.findall(r"`([^`]+)`", m.group(3))))
if not layers:
    sys.exit(f"{doc_path}: no layer table under '## Layers'")


def layer_of(relative):
    """The layer of a path relative to include/rsfcycle/ or source/."""
    found = []
    for number, name, patterns in layers:
        for pattern in patterns:
            if pattern.endswith("/"):
                hit = relative.startswith(pattern)
            elif pattern.endswith(".*"):
                hit = os.path.splitext(relative)[0] == pattern[:-2]
            else:
                hit = relative == pattern
            if hit:
                found.append((len(pattern), number, name))
    # the longest pattern wins (a file named beside its folder's layer)
    return max(found) if found else None


files = {}
for folder in ("include/rsfcycle", "source"):
    for path in glob.glob(os.path.join(root, folder, "**", "*"), recursive=True):
        if path.endswith((".h", ".cc")):
            files[path] = os.path.relpath(path, os.path.join(root, folder))

failures = []
for path, relative in sorted(files.items()):
    shown = os.path.relpath(path, root)
    layer = layer_of(relative)
    if layer is None:
        failures.append(f"{shown}: in no layer of doc/architecture.md")
        continue
    text = open(path).read()
    for included in re.findall(r"#include\s*<rsfcycle/([^>]+)>", text):
        target = layer_of(included)
        if target is None:
            failures.append(f"{shown} includes {included}: in no layer")
        elif target[1] > layer[1]:
            failures.append(
                f"{shown} (layer {layer[1]} {layer[2]}) includes "
                f"{included} (layer {target[1]} {target[2]}): the include "
                "runs up")
    stem = os.path.splitext(relative)[0]
    if not re.search(r"`" + re.escape(stem) + r"\.(h|cc|\*)`", doc):
        failures.append(f"{shown}: not named in doc/architecture.md")
    n_lines = text.count("\n")
    if n_lines > 600:
        failures.append(f"{shown}: {n_lines} lines, more than 600")

# every file the doc names exists
known = {os.path.splitext(r)[0] for r in files.values()}
for name in set(re.findall(r"`([\w/]+)\.(?:h|cc|\*)`", doc)):
    if name != name.lower():
        continue  # a placeholder such as friction/NAME_law.h
    folders = {os.path.dirname(r).split("/")[0] for r in files.values()}
    if name.split("/")[0] in folders - {""} or name in {
            os.path.splitext(r)[0] for r in files.values() if "/" not in r}:
        if name not in known:
            failures.append(f"doc/architecture.md names {name}: no such file")


# 5. Functions: a line holding only "{" whose head (the lines above it up
# to a blank line, a ';' or a brace) is a function's signature, and the
# first line below it holding only "}" at the same indentation.
CONTROL = {"if", "for", "while", "switch", "else", "do", "try", "catch",
           "namespace", "class", "struct", "enum", "union", "extern",
           "return"}


def long_functions(path, limit=80):
    """[(name, body lines, line)] of the functions in a file whose body is
    longer than limit lines; a constructor's name is "Class constructor"."""
    lines = open(path, encoding="utf-8").read().split("\n")
    found = []
    for i, line in enumerate(lines):
        m = re.match(r"^(\s*)\{\s*$", line)
        if not m:
            continue
        head, j = [], i - 1
        while j >= 0:
            s = lines[j].strip()
            if (not s or s.endswith((";", "{", "}")) or
                    s.startswith(("//", "*", "/*", "#"))):
                break
            head.insert(0, s)
            j -= 1
        text = " ".join(head)
        first = re.match(r"[\w:~]+", text)
        if ("(" not in text or (first and first.group(0) in CONTROL) or
                re.match(r"(template\s*<[^>]*>\s*)?"
                         r"(class|struct|enum|union|namespace)\b", text) or
                ("=" in text.split("(")[0] and "operator" not in text)):
            continue
        signature = re.sub(r"<[^<>]*>", "", re.sub(r"<[^<>]*>", "", text))
        name = re.search(r"([\w:~]+|operator\S+)\s*\(", signature)
        if not name or name.group(1) in CONTROL:
            continue
        k = i + 1
        close = re.compile("^" + m.group(1) + r"\}[;,)]*\s*$")
        while k < len(lines) and not close.match(lines[k]):
            k += 1
        if k < len(lines) and k - i - 1 > limit:
            parts = name.group(1).split("::")
            label = (parts[-2] + " constructor" if len(parts) > 1 and
                     parts[-1] == parts[-2] else "::".join(parts[-2:]))
            found.append((label, k - i - 1, i + 1))
    return found


listed = {}  # name -> lines, from the doc's bullets
section = doc.split("## Functions longer than 80 lines", 1)
if len(section) < 2:
    failures.append("doc/architecture.md: no section 'Functions longer "
                    "than 80 lines'")
else:
    bullets = section[1].split("\n## ", 1)[0]
    for name, constructor, lines in re.findall(
            r"^- `([^`]+)`((?: constructor)?) \((\d+) lines\)", bullets,
            re.M):
        listed[name + constructor] = int(lines)
measured = {}
for path, relative in sorted(files.items()):
    for name, lines, line in long_functions(path):
        if name.endswith("declare_parameters"):
            continue
        shown = f"{os.path.relpath(path, root)}:{line}"
        measured[name] = lines
        if name not in listed:
            failures.append(f"{shown}: {name} has {lines} lines, more than "
                            "80, and doc/architecture.md does not name it "
                            "with a reason")
        elif listed[name] != lines:
            failures.append(f"{shown}: {name} has {lines} lines, "
                            f"doc/architecture.md says {listed[name]}")
for name in sorted(set(listed) - set(measured)):
    failures.append(f"doc/architecture.md names {name} as longer than 80 "
                    "lines: it is not (or does not exist)")

for failure in failures:
    print(failure)
print(f"architecture: {len(files)} files, {len(layers)} layers, "
      f"{len(measured)} functions over 80 lines named, "
      f"{len(failures)} violations")
sys.exit(1 if failures else 0)
