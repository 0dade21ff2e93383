#!/usr/bin/python3
"""Runs the fenced blocks of one markdown file as tests (docs/contributing.md, "Docs are tests").

    run_doc_blocks.py --source SRC --build BUILD [--prefix PREFIX] [--long] FILE.md

The blocks run in order in a scratch directory that looks like a checkout: copies of SRC's maps/,
docs/, scripts/, tests/, examples/, bench/ and python/ (8 MB; a block that writes over a shipped
file never touches the source), `build` -> BUILD and an empty `out/`.
`ceilplan` is BUILD/app/ceilplan and the Python module is BUILD/python.

Kinds: `$ ` sessions (console, sh or untyped blocks whose first line starts with `$ `) run each
command with bash and compare what it prints with the lines below it; `sh` blocks run; `python`
blocks run in one interpreter per file and an untyped block right after one is its output; `cpp`
blocks compile against the package installed in PREFIX (and run if they have main()); usage
synopses (`ceilplan CMD ... [--flag X]`) are checked against `ceilplan CMD --help`; `json` is
parsed; `yaml` is written (`file=`) and checked (`check=`). Other untyped blocks are text
(equations, data, excerpts); one that starts with a command is an error: it needs `$ ` or sh.

Markers, HTML comments on the lines above a block, one directive each:
    <!-- doc-test: long -->            run only by scripts/doc-tests-long
    <!-- doc-test: skip REASON -->     not run; the reason is printed
    <!-- doc-test: file=PATH -->       write the block to PATH (in the scratch directory)
    <!-- doc-test: append-to=PATH -->  ... after the contents of PATH (a fragment of a file)
    <!-- doc-test: check=COMMAND -->   run COMMAND after writing the block; it must exit 0
    <!-- doc-test: setup=COMMAND -->   run COMMAND before the block (files the prose describes)
    <!-- doc-test: tolerance=R -->     relative tolerance for the block's numbers (default 1e-3)
    <!-- doc-test: ignore=REGEX -->    text matching REGEX differs from run to run (timings)
    <!-- doc-test: cpp-args=DECLS -->  a C++ fragment's free names, as function parameters
    <!-- doc-test: table=COMMAND -->   above a markdown table: COMMAND prints its rows
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

DEFAULT_TOLERANCE = 1e-3
LINKED_TREES = ("maps", "docs", "scripts", "tests", "examples", "bench", "python")
COMMAND_START = re.compile(r"^(build/|scripts/|bench/|tests/|ceilplan |mkdir |cmake |nice |python3 |cd )")
SYNOPSIS = re.compile(r"^ceilplan [a-z-]+ .*(\[--|[A-Z]{3,})")
MARKER = re.compile(r"^<!-- doc-test: ([a-z-]+)(?:[= ](.*?))? -->$")
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
KNOWN_MARKERS = {"table", "long", "skip", "file", "append-to", "check", "setup", "tolerance", "ignore", "cpp-args",
                 "exit"}


class Block:
    def __init__(self, path, line, lang, lines, markers):
        self.path, self.line, self.lang, self.lines = path, line, lang, lines
        self.markers = markers  # list of (name, value)
        self.kind = None
        self.output = None  # the untyped block that shows a python block's output

    def marker(self, name):
        values = [v for n, v in self.markers if n == name]
        return values[-1] if values else None

    def all(self, name):
        return [v for n, v in self.markers if n == name]

    def where(self):
        return f"{self.path}:{self.line}"


class Failure(Exception):
    pass


def parse_blocks(path, text):
    blocks, lines = [], text.split("\n")
    i = 0
    while i < len(lines):
        fence = re.match(r"^```(\S*)\s*$", lines[i])
        table = lines[i].startswith("|") and i > 0 and MARKER.match(lines[i - 1].strip()) is not None
        if not fence and not table:
            i += 1
            continue
        markers, j = [], i - 1
        while j >= 0 and (lines[j].strip() == "" or MARKER.match(lines[j].strip())):
            m = MARKER.match(lines[j].strip())
            if m:
                if m.group(1) not in KNOWN_MARKERS:
                    raise Failure(f"{path}:{j + 1}: unknown doc-test marker '{m.group(1)}'; known: "
                                  + ", ".join(sorted(KNOWN_MARKERS)))
                markers.insert(0, (m.group(1), m.group(2) or ""))
            j -= 1
        if table:  # a markdown table whose rows a command prints (table=COMMAND)
            end = i
            while end < len(lines) and lines[end].startswith("|"):
                end += 1
            blocks.append(Block(path, i + 1, "table", lines[i:end], markers))
            i = end
            continue
        end = i + 1
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        if end == len(lines):
            raise Failure(f"{path}:{i + 1}: code fence never closed")
        blocks.append(Block(path, i + 1, fence.group(1), lines[i + 1:end], markers))
        i = end + 1
    return blocks


def classify(blocks):
    previous = None
    for block in blocks:
        first = next((l for l in block.lines if l.strip()), "")
        if block.lang in ("console", "sh", "") and first.startswith("$ "):
            block.kind = "session"
        elif block.lang == "sh":
            block.kind = "sh"
        elif block.lang in ("python", "cpp", "json", "yaml", "table", "cmake"):
            block.kind = block.lang
        elif block.lang == "" and previous is not None and previous.kind == "python" and previous.output is None:
            block.kind = "output"
            previous.output = block
        elif block.lang == "" and SYNOPSIS.match(first):
            block.kind = "synopsis"
        elif block.lang == "" and COMMAND_START.match(first) and (block.marker("skip") or block.marker("long")):
            block.kind = "sh"  # commands left to scripts/doc-tests-long or skipped
        elif block.lang == "":
            block.kind = "text"
            if COMMAND_START.match(first):
                raise Failure(f"{block.where()}: this block starts with a command ('{first[:60]}'): fence it as "
                              "```sh, write it as a `$ ` session, or mark it <!-- doc-test: skip REASON -->")
        else:
            raise Failure(f"{block.where()}: no runner for ```{block.lang} blocks")
        previous = block


# ---------------------------------------------------------------- output comparison

def split_numbers(line):
    parts, numbers, last = [], [], 0
    for m in NUMBER.finditer(line):
        # A digit glued to a name (bench_tour2, EPSG:25832 stays a number) is text.
        if m.start() > 0 and (line[m.start() - 1].isalpha() or line[m.start() - 1] == "_"):
            continue
        parts.append(line[last:m.start()])
        numbers.append(m.group(0))
        last = m.end()
    parts.append(line[last:])
    return parts, numbers


def numbers_match(expected, actual, tolerance):
    if "." not in expected and "e" not in expected.lower():
        return expected.lstrip("+") == actual.lstrip("+")  # counts are exact
    try:
        e, a = float(expected), float(actual)
    except ValueError:
        return expected == actual
    digits = expected.lower().split("e")[0]
    last_place = 10.0 ** -(len(digits.split(".")[1])) if "." in digits else 1.0
    if "e" in expected.lower():
        last_place *= 10.0 ** int(expected.lower().split("e")[1])
    return abs(e - a) <= max(tolerance * abs(e), last_place * 1.0000001)


def line_matches(expected, actual, tolerance):
    if expected == actual:
        return True
    ep, en = split_numbers(expected)
    ap, an = split_numbers(actual)
    # Column padding moves with a number's width; the words between numbers must agree.
    if len(en) != len(an) or [" ".join(p.split()) for p in ep] != [" ".join(p.split()) for p in ap]:
        return False
    return all(numbers_match(e, a, tolerance) for e, a in zip(en, an))


def normalise(lines, ignores):
    out = []
    for line in lines:
        line = line.rstrip()
        for pattern in ignores:
            line = re.sub(pattern, "<varies>", line)
        out.append(line)
    while out and not out[-1]:
        out.pop()
    while out and not out[0]:
        out.pop(0)
    return out


def compare(expected, actual, tolerance, ignores):
    """None if the lines match, else a description of the first difference."""
    expected, actual = normalise(expected, ignores), normalise(actual, ignores)

    furthest = []  # the failure that got furthest through the doc's lines is the one to show

    def failed(i, j, why):
        if not furthest or (i, j) > furthest[0][:2]:
            furthest[:] = [(i, j, why)]
        return False

    def match(i, j):
        while i < len(expected):
            if expected[i].strip() == "...":
                if i + 1 == len(expected):
                    return True
                return any(match(i + 1, k) for k in range(j, len(actual) + 1))
            if j >= len(actual):
                return failed(i, j, "output ended")
            if not line_matches(expected[i], actual[j], tolerance):
                return failed(i, j, None)
            i, j = i + 1, j + 1
        return j == len(actual) or failed(i, j, "extra output")

    if match(0, 0):
        return None
    i, j, why = furthest[0]
    want = expected[i] if i < len(expected) else "(end of the block)"
    got = actual[j] if j < len(actual) else "(end of the output)"
    return f"first difference at expected line {i + 1}{' (' + why + ')' if why else ''}:\n" \
           f"    doc: {want}\n    got: {got}"


# ---------------------------------------------------------------- the scratch checkout

def make_scratch(source, build):
    scratch = tempfile.mkdtemp(prefix="ceilplan-doc-")
    for tree in LINKED_TREES:
        shutil.copytree(os.path.join(source, tree), os.path.join(scratch, tree), symlinks=True,
                        ignore=shutil.ignore_patterns("__pycache__"))
    for name in ("README.md", "CMakeLists.txt"):
        shutil.copy(os.path.join(source, name), scratch)
    os.symlink(os.path.abspath(build), os.path.join(scratch, "build"))
    os.makedirs(os.path.join(scratch, "out"))
    return scratch


class Runner:
    def __init__(self, args, path, blocks):
        self.args, self.path, self.blocks = args, path, blocks
        self.build = os.path.abspath(args.build)
        self.scratch = make_scratch(os.path.abspath(args.source), self.build)
        self.env = dict(os.environ)
        self.env["PATH"] = os.path.join(self.build, "app") + os.pathsep + self.env.get("PATH", "")
        self.env["PYTHONPATH"] = os.path.join(self.build, "python")
        self.env["MPLBACKEND"] = "Agg"
        self.env.pop("CEILPLAN_SOURCE_DIR", None)
        self.counts = {k: 0 for k in ("run", "compiled", "synopsis", "checked", "long", "skipped", "text")}
        self.failures = []
        self.python_results = None
        self.cpp_results = None

    def shell(self, command, timeout=900):
        started = time.time()
        result = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=self.scratch, env=self.env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                                timeout=timeout)
        return result.returncode, result.stdout, time.time() - started

    def fail(self, block, line, command, message):
        self.failures.append(f"{self.path}:{line}: {command}\n  {message}")

    def prepare(self, block):
        for command in block.all("setup"):
            code, out, _ = self.shell(command)
            if code:
                raise Failure(f"setup '{command}' exited with {code}: {out.strip()[:300]}")

    # ---------------------------------------------------------- kinds

    def run_session(self, block):
        commands, i = [], 0
        lines = block.lines
        while i < len(lines):
            if not lines[i].startswith("$ "):
                i += 1
                continue
            start, command = i, lines[i][2:]
            while command.rstrip().endswith("\\") and i + 1 < len(lines):
                i += 1
                command = command.rstrip()[:-1] + " " + lines[i].strip()
            expected = []
            i += 1
            while i < len(lines) and not lines[i].startswith("$ "):
                expected.append(lines[i])
                i += 1
            commands.append((block.line + 1 + start, command, expected))
        tolerance = float(block.marker("tolerance") or DEFAULT_TOLERANCE)
        for line, command, expected in commands:
            code, out, seconds = self.shell(command)
            shown = command if len(command) < 160 else command[:157] + "..."
            errors = [l for l in expected if re.match(r"^ceilplan: (error|no path)", l)]
            if errors and code == 0:
                self.fail(block, line, shown, "the doc shows an error but the command exited with 0")
                continue
            if not errors and code != 0:
                self.fail(block, line, shown, f"exit code {code}; output:\n    "
                          + "\n    ".join(out.strip().splitlines()[-6:]))
                continue
            difference = compare(expected, out.split("\n"), tolerance, block.all("ignore"))
            if difference:
                if self.args.verbose:
                    difference += "\n  the whole output:\n" + "\n".join(out.rstrip().split("\n")[:60])
                self.fail(block, line, shown, difference)
            if self.args.verbose:
                print(f"  {self.path}:{line}: {seconds:.1f} s: {shown}")

    def run_sh(self, block):
        script = "set -e\n" + "\n".join(block.lines)
        code, out, seconds = self.shell(script)
        if code:
            self.fail(block, block.line, "(sh block)", f"exit code {code}; output:\n    "
                      + "\n    ".join(out.strip().splitlines()[-6:]))
        if self.args.verbose:
            print(f"  {block.where()}: sh block, {seconds:.1f} s")

    def write_file(self, block):
        target = block.marker("file")
        if not target:
            return None
        full = os.path.join(self.scratch, target)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        text = "\n".join(block.lines) + "\n"
        base = block.marker("append-to")
        if base:
            with open(os.path.join(self.scratch, base)) as f:
                text = f.read().rstrip("\n") + "\n" + text
        if os.path.islink(full):
            os.unlink(full)
        with open(full, "w") as f:
            f.write(text)
        return target

    def run_checks(self, block):
        for command in block.all("check"):
            code, out, _ = self.shell(command)
            if code:
                self.fail(block, block.line, command, f"check exited with {code}:\n    "
                          + "\n    ".join(out.strip().splitlines()[-6:]))

    def run_json(self, block):
        text = "\n".join(block.lines)
        try:
            json.loads(text)
        except json.JSONDecodeError as error:
            self.fail(block, block.line + 1 + error.lineno - 1, "(json block)", f"not JSON: {error.msg}")

    def run_synopsis(self, block):
        text = " ".join(block.lines)
        command = text.split()[1]
        code, help_text, _ = self.shell(f"ceilplan {command} --help")
        if code:
            self.fail(block, block.line, f"ceilplan {command} --help", f"exit code {code}")
            return
        known = set(re.findall(r"--[a-z][a-z0-9-]*", help_text))
        for flag in sorted(set(re.findall(r"--[a-z][a-z0-9-]*", text))):
            if flag not in known:
                self.fail(block, block.line, f"ceilplan {command} --help",
                          f"the synopsis shows {flag}, which `ceilplan {command} --help` does not list")

    def run_cmake(self, block):
        """A CMake project that uses the package: configured against the installed prefix, with an
        empty program for each source it names (`NAME.cpp`, or foreach(VAR a b c) over VAR.cpp), so
        that find_package's version check and the targets it links are what is tested."""
        if not self.args.prefix:
            raise Failure(f"{block.where()}: cmake blocks need --prefix (the installed package)")
        project = os.path.join(self.scratch, f".cmake_{block.line}")
        os.makedirs(project)
        text = "\n".join(block.lines)
        sources = set(re.findall(r"\b(\w+)\.cpp\b", text))
        for variable, items in re.findall(r"foreach\((\w+)\s+([^)]*)\)", text):
            if "${" + variable + "}.cpp" in text:
                sources.update(items.split())
        for name in sources:
            with open(os.path.join(project, name + ".cpp"), "w") as f:
                f.write("int main() { return 0; }\n")
        with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
            f.write(text + "\n")
        code, out, _ = self.shell(f"cmake -S {project} -B {project}/build -DCMAKE_PREFIX_PATH={self.args.prefix} 2>&1")
        if code:
            self.fail(block, block.line, "(cmake block)", "configuring it against the installed package failed:\n    "
                      + "\n    ".join(out.strip().splitlines()[-8:]))

    def run_table(self, block):
        command = block.marker("table")
        if not command:
            raise Failure("a table is checked against a command: table=COMMAND")
        code, out, _ = self.shell(command)
        if code:
            self.fail(block, block.line, command, f"exit code {code}:\n    " + "\n    ".join(out.strip().splitlines()[-6:]))
            return
        rows = block.lines[2:]  # below the header and its rule
        tolerance = float(block.marker("tolerance") or DEFAULT_TOLERANCE)
        difference = compare(rows, out.split("\n"), tolerance, block.all("ignore"))
        if difference:
            self.fail(block, block.line, command, difference)

    # ---------------------------------------------------------- python, one interpreter per file

    def run_python_all(self, blocks):
        for block in blocks:
            self.prepare(block)
        sources = [{"line": b.line, "code": "\n".join(b.lines)} for b in blocks]
        driver = os.path.join(self.scratch, ".doc_python_blocks.json")
        with open(driver, "w") as f:
            json.dump(sources, f)
        separator = "@@doc-block-end@@"
        program = (
            "import json, sys, traceback\n"
            f"blocks = json.load(open({driver!r}))\n"
            "scope = {'__name__': '__main__'}\n"
            "for b in blocks:\n"
            "    try:\n"
            "        exec(compile(b['code'], 'block at line %d' % b['line'], 'exec'), scope)\n"
            "        status = 'ok'\n"
            "    except BaseException:\n"
            "        traceback.print_exc(file=sys.stdout)\n"
            "        status = 'raised'\n"
            f"    print({separator!r}, status, flush=True)\n")
        result = subprocess.run([sys.executable, "-c", program], cwd=self.scratch, env=self.env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                                timeout=1800)
        chunks, current = [], []
        for line in result.stdout.split("\n"):
            if line.startswith(separator):
                chunks.append((current, line.split()[-1]))
                current = []
            else:
                current.append(line)
        self.python_results = {}
        for index, block in enumerate(blocks):
            if index < len(chunks):
                self.python_results[block.line] = chunks[index]
            else:
                self.python_results[block.line] = (current, "died (exit %d)" % result.returncode)

    def run_python(self, block):
        lines, status = self.python_results[block.line]
        if status != "ok":
            self.fail(block, block.line, "(python block)", f"{status}:\n    " + "\n    ".join(lines[-8:]))
            return
        if block.output is not None:
            tolerance = float(block.output.marker("tolerance") or block.marker("tolerance") or DEFAULT_TOLERANCE)
            difference = compare(block.output.lines, lines, tolerance, block.all("ignore") + block.output.all("ignore"))
            if difference:
                if self.args.verbose:
                    difference += "\n  the whole output:\n" + "\n".join(lines[:60])
                self.fail(block, block.output.line, "(output of the python block at line %d)" % block.line, difference)

    # ---------------------------------------------------------- C++

    def run_cpp_all(self, blocks):
        if not self.args.prefix:
            raise Failure(f"{blocks[0].where()}: C++ blocks need --prefix (the installed package)")
        project = os.path.join(self.scratch, ".cpp")
        os.makedirs(project)
        targets = []
        for block in blocks:
            name = f"block_{block.line}"
            code = "\n".join(block.lines)
            if not re.search(r"\bint\s+main\s*\(", code):
                includes = [l for l in block.lines if l.startswith("#include")]
                body = [l for l in block.lines if not l.startswith("#include")]
                header = includes if includes else ["#include <ceilplan/ceilplan.hpp>", "#include <iostream>"]
                # using-directives and namespace aliases stay at namespace scope before the body
                scope = [l for l in body if re.match(r"^(using namespace|namespace \w+ =)", l)]
                body = [l for l in body if l not in scope]
                code = "\n".join(header + scope + [f"[[maybe_unused]] void docBlock({block.marker('cpp-args') or ''}) {{"]
                                 + body + ["}"])
            with open(os.path.join(project, name + ".cpp"), "w") as f:
                f.write(code + "\n")
            targets.append((block, name, "int main" in code))
        with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
            f.write("cmake_minimum_required(VERSION 3.22)\nproject(doc_blocks LANGUAGES CXX)\n"
                    "set(CMAKE_CXX_STANDARD 17)\nfind_package(ceilplan REQUIRED)\n")
            for block, name, has_main in targets:
                if has_main:
                    f.write(f"add_executable({name} {name}.cpp)\n")
                else:
                    f.write(f"add_library({name} OBJECT {name}.cpp)\n")
                # A fragment's results are what it shows: they may go unused.
                warnings = "-Wall -Wextra" + ("" if has_main else " -Wno-unused")
                f.write(f"target_link_libraries({name} PRIVATE ceilplan::ceilplan)\n"
                        f"target_compile_options({name} PRIVATE {warnings})\n")
        code, out, _ = self.shell(f"cmake -S .cpp -B .cpp/build -DCMAKE_BUILD_TYPE=Release "
                                  f"-DCMAKE_PREFIX_PATH={self.args.prefix} >/dev/null")
        if code:
            raise Failure(f"{blocks[0].where()}: configuring the C++ blocks failed:\n{out[-2000:]}")
        self.cpp_results = {}
        for block, name, has_main in targets:
            code, out, _ = self.shell(f"cmake --build .cpp/build --target {name} 2>&1")
            errors = [l for l in out.split("\n") if "error" in l or "warning" in l]
            if code:
                self.cpp_results[block.line] = "does not compile:\n    " + "\n    ".join(errors[:6])
            elif errors:
                self.cpp_results[block.line] = "compiles with warnings:\n    " + "\n    ".join(errors[:6])
            elif has_main:
                code, out, _ = self.shell(f".cpp/build/{name}")
                expected = int(block.marker("exit") or 0)  # a program showing an error exits with its code
                self.cpp_results[block.line] = (None if code == expected else
                                                f"exit code {code} (expected {expected}): {out[-500:]}")
            else:
                self.cpp_results[block.line] = None

    def run_cpp(self, block):
        problem = self.cpp_results.get(block.line)
        if problem:
            self.fail(block, block.line, "(cpp block)", problem)

    # ---------------------------------------------------------- driver

    def run_python_block(self, block):
        if self.python_results is None:  # one interpreter for the file's python blocks
            self.run_python_all([b for b in self.blocks if b.kind == "python" and self.wanted(b)])
        self.run_python(block)

    def run_cpp_block(self, block):
        if self.cpp_results is None:  # one CMake project for the file's C++ blocks
            self.run_cpp_all([b for b in self.blocks if b.kind == "cpp" and self.wanted(b)])
        self.run_cpp(block)

    def run_file_block(self, block, target):
        if block.kind == "json" and target is None:
            self.run_json(block)
        if block.kind == "yaml" and target is None and not block.all("check"):
            raise Failure("a yaml block needs file= and check= markers (or skip)")
        self.run_checks(block)

    def run(self):
        # kind: (what runs it, what it counts as)
        kinds = {"session": (self.run_session, "run"), "sh": (self.run_sh, "run"),
                 "python": (self.run_python_block, "run"), "cpp": (self.run_cpp_block, "compiled"),
                 "synopsis": (self.run_synopsis, "synopsis"), "table": (self.run_table, "checked"),
                 "cmake": (self.run_cmake, "checked")}
        for block in self.blocks:
            if block.kind in ("text", "output"):
                self.counts["text"] += 1
                self.write_file(block)  # data the next blocks read (file=)
                continue
            reason = block.marker("skip")
            if reason is not None:
                self.counts["skipped"] += 1
                print(f"skipped {block.where()} ({block.kind}): {reason}")
                continue
            if block.marker("long") is not None and not self.args.long:
                self.counts["long"] += 1
                continue
            try:
                if block.kind != "python":  # python blocks run together: their setup runs before all of them
                    self.prepare(block)
                target = self.write_file(block)
                if block.kind in ("json", "yaml"):
                    self.run_file_block(block, target)
                    self.counts["checked"] += 1
                else:
                    runner, count = kinds[block.kind]
                    runner(block)
                    self.counts[count] += 1
            except Failure as failure:
                self.fail(block, block.line, f"({block.kind} block)", str(failure))
            except subprocess.TimeoutExpired as timeout:
                self.fail(block, block.line, f"({block.kind} block)", f"timed out after {timeout.timeout} s")

    def wanted(self, block):
        return block.marker("skip") is None and (self.args.long or block.marker("long") is None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--prefix", help="the package installed with cmake --install (for cpp blocks)")
    parser.add_argument("--long", action="store_true", help="also run the blocks marked long")
    parser.add_argument("--keep", action="store_true", help="keep the scratch directory")
    parser.add_argument("--verbose", action="store_true", help="print each command and its time")
    parser.add_argument("file")
    args = parser.parse_args()
    # The blocks run in a scratch directory: paths given relative to here must not move with them.
    for name in ("source", "build", "prefix", "file"):
        if getattr(args, name):
            setattr(args, name, os.path.abspath(getattr(args, name)))
    relative = os.path.relpath(os.path.abspath(args.file), os.path.abspath(args.source))
    with open(args.file) as f:
        text = f.read()
    try:
        blocks = parse_blocks(relative, text)
        classify(blocks)
    except Failure as failure:
        print(f"FAILED: {failure}")
        return 1
    runner = Runner(args, relative, blocks)
    try:
        runner.run()
    finally:
        if args.keep:
            print(f"scratch directory kept: {runner.scratch}")
        else:
            shutil.rmtree(runner.scratch, ignore_errors=True)
    c = runner.counts
    print(f"{relative}: {len(blocks)} blocks: {c['run']} run, {c['compiled']} compiled, {c['synopsis']} checked as "
          f"synopsis, {c['checked']} files checked, {c['long']} skipped as long, {c['skipped']} skipped with reason, "
          f"{c['text']} text or output; {len(runner.failures)} failed")
    for failure in runner.failures:
        print("FAILED: " + failure)
    return 1 if runner.failures else 0


if __name__ == "__main__":
    sys.exit(main())
