#!/usr/bin/env python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""scripts/check-docs fails on drift: a snippet that differs from its source, a block without a
source or language, a command that fails, a synopsis that is not the program's. Runs the checker
on a small made-up repository (and a stand-in `shapecorr --help`) and checks each verdict.

usage: test_check_docs.py CHECK_DOCS
"""
import pathlib
import subprocess
import sys
import tempfile

EXAMPLE = """// an example
int main() {
  //! [body]
  int x = 1;
  return x - 1;
  //! [body]
}
"""


def make_repo(top, readme):
    root = top / "repo"
    (root / "doc").mkdir(parents=True)
    (root / "examples" / "m").mkdir(parents=True)
    (root / "examples" / "m" / "a.cpp").write_text(EXAMPLE)
    (root / "README.md").write_text(readme)
    build = top / "build"
    (build / "tools").mkdir(parents=True)
    fake = build / "tools" / "shapecorr"
    fake.write_text("#!/bin/sh\necho 'usage:'\necho '  shapecorr info MESH [--json]'\n")
    fake.chmod(0o755)
    return root, build


def run(check_docs, mode, root, build):
    args = [sys.executable, check_docs, mode, str(root)] + (["--build", str(build)] if mode == "commands" else [])
    r = subprocess.run(args, capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout + r.stderr


def main():
    check_docs = sys.argv[1]
    good = ("<!-- snippet: examples/m/a.cpp [body] -->\n```cpp\nint x = 1;\nreturn x - 1;\n```\n\n"
            "```sh\ntrue\n```\n\n<!-- synopsis -->\n```text\nshapecorr info MESH [--json]\n```\n")
    cases = [
        ("agrees", good, 0, 0, None),
        ("snippet drift", good.replace("return x - 1;\n```", "return x;\n```"), 1, None, "differs from examples/m/a.cpp [body]"),
        ("no source", good.replace("<!-- snippet: examples/m/a.cpp [body] -->\n", ""), 1, None, "without '<!-- snippet"),
        ("unknown source", good.replace("examples/m/a.cpp", "examples/m/b.cpp"), 1, None, "not a compiled example"),
        ("no language", good + "\n```\nsomething\n```\n", 1, None, "block language ''"),
        ("failing command", good.replace("```sh\ntrue\n```", "```sh\nfalse\n```"), 0, 1, "exit 1: false"),
        ("synopsis drift", good.replace("```text\nshapecorr info MESH [--json]", "```text\nshapecorr info MESH --json"), 0, 1,
         "is not a synopsis"),
        ("not run", good.replace("```sh\ntrue\n```", "<!-- not run: a demonstration -->\n```sh\nfalse\n```"), 0, 0, None),
    ]
    failures = 0
    for name, readme, want_snippets, want_commands, message in cases:
        with tempfile.TemporaryDirectory() as t:
            root, build = make_repo(pathlib.Path(t), readme)
            got_s, out_s = run(check_docs, "snippets", root, build)
            got_c, out_c = (run(check_docs, "commands", root, build) if want_commands is not None else (None, ""))
        ok = got_s == want_snippets and (want_commands is None or got_c == want_commands)
        if message is not None and message not in out_s + out_c:
            ok = False
        print(f"{'ok' if ok else 'FAILED'}: {name} (snippets exit {got_s}, commands exit {got_c})")
        if not ok:
            failures += 1
            print(out_s + out_c)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
