#!/usr/bin/python3
"""Every command quoted in README.md and docs/*.md still parses, and what it names exists.

A quoted command is a line of a fenced block, or an inline `code` span, that runs one of the
project's programs: build/<program> (possibly behind `mpirun ... ` or `srun ... `), scripts/<file>,
or `/usr/bin/python3 <file>`. For each one (a fenced line ending in `\\` goes on on the next line;
`a && b` is two commands; `# ...` is a comment; `[...]` marks an optional part, checked as given):

- the program exists: build/<program> in the build folder given, any other path in the repository;
- `thinlayer`: its command (solve, study, verify) exists, a study is one the help of `study` lists,
  and every option is one that command's --help declares, given once, a value option followed by a
  value (never another option), a flag by none — the rules thinlayer's own parser applies;
- any other program: every option it is given is named in its own --help (or usage) text, where that
  text names options at all;
- every input it names exists: a path into the repository's folders (cases/..., scripts/..., ...),
  and the file of `--scene`, `--joint`, `--exporter`, `--problem`. Outputs (`--out`, `--vtu`, ...)
  are not inputs. A name in capitals (FILE, DIR, FILE.json, DIR/results.h5) is a placeholder.

Nothing is run but the programs' --help. Each failure names the file, the line and what is wrong.

    /usr/bin/python3 tests/test_doc_commands.py BUILD_DIR
"""

import glob
import os
import re
import shlex
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BUILD = None  # the build folder (argv[1]): where build/<program> is

# The repository's folders: a token that starts with one of them names a file that must exist.
REPO_FOLDERS = ("cases/", "scripts/", "tests/", "report/", "reference/", "benchmarks/", "docs/", "core/",
                "studies/")
# Options whose value is a file the command reads (the others' values are not inputs).
INPUT_OPTIONS = {"--scene", "--joint", "--exporter", "--problem"}
LAUNCHERS = {"mpirun", "mpiexec", "srun"}


def placeholder(token):
    """FILE, DIR, FILE.json, DIR/results.h5, F1,F2,...: a name the reader replaces."""
    head = token.split("/")[0].split(".")[0]
    return bool(re.fullmatch(r"[A-Z][A-Z0-9_]*", head))


# ---------------------------------------------------------------------------------------------
# Where the commands are
# ---------------------------------------------------------------------------------------------

def documents():
    return [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))


def runs_a_program(text):
    words = text.split()
    while words and (words[0] in LAUNCHERS or words[0].startswith("-") or re.fullmatch(r"\d+", words[0])):
        words = words[1:]  # mpirun -n 2 ..., srun --mpi=pmix ...
    # (the interpreter alone is named, not run: "`/usr/bin/python3` imports getfem")
    return bool(words) and (words[0].startswith("build/") or words[0].startswith("scripts/") or
                            (words[0] == "/usr/bin/python3" and len(words) > 1))


def quoted_commands(path):
    """(line number, command text) of every command quoted in one Markdown file."""
    lines = open(path, encoding="utf-8").read().split("\n")
    found, fenced, pending = [], False, None
    prose = []
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            fenced, pending = not fenced, None
            prose.append("")
            continue
        if fenced:
            prose.append("")
            text = line.strip()
            if pending:  # the continuation of a line that ended in a backslash
                start, before = pending
                text, pending = before + " " + text, None
            else:
                start = number
            if text.endswith("\\"):
                pending = (start, text[:-1])
                continue
            found.append((start, text))
        else:
            prose.append(line)
    # Inline spans, which may wrap over lines in the prose.
    joined = "\n".join(prose)
    for match in re.finditer(r"`([^`]+)`", joined):
        found.append((joined.count("\n", 0, match.start()) + 1, match.group(1).replace("\n", " ")))
    commands = []
    for number, text in found:
        text = re.sub(r"(^|\s)#.*$", "", text).strip()  # a comment
        for part in text.split("&&"):
            part = part.strip()
            if runs_a_program(part):
                commands.append((number, part))
    return commands


# ---------------------------------------------------------------------------------------------
# What the programs declare
# ---------------------------------------------------------------------------------------------

_help_cache = {}


def help_text(argv):
    key = tuple(argv)
    if key not in _help_cache:
        try:
            r = subprocess.run(argv + ["--help"], capture_output=True, text=True, timeout=60,
                               stdin=subprocess.DEVNULL)
            _help_cache[key] = (r.returncode, r.stdout + r.stderr)
        except OSError as e:
            _help_cache[key] = (-1, str(e))
    return _help_cache[key]


def thinlayer_options(program, command):
    """{--name: takes a value} from `thinlayer COMMAND --help` (a value option shows its value's
    name after it: `--eps E`; a flag shows none)."""
    code, text = help_text([program, command])
    if code != 0:
        raise AssertionError("thinlayer %s --help exited %d: %s" % (command, code, text.strip()[:200]))
    options = {}
    for line in text.split("\n"):  # a declaration stands two spaces in; its help text 23
        m = re.match(r"  (?:-\w,)?(--[\w-]+)( [A-Z][^ ]*)?(\s|$)", line)
        if m:
            options.setdefault(m.group(1), m.group(2) is not None)
    return options, text


def thinlayer_studies(program):
    """The study names `thinlayer study --help` lists under "Studies:"."""
    _, text = thinlayer_options(program, "study")
    studies, inside = set(), False
    for line in text.split("\n"):
        if line.startswith("Studies:"):
            inside = True
            continue
        if inside:
            if line.strip() and not line.startswith("  "):
                break  # the next paragraph (the list itself may hold a blank line)
            m = re.match(r"  ([a-z][\w-]*)\s", line)
            if m:
                studies.add(m.group(1))
    return studies


# ---------------------------------------------------------------------------------------------
# One command
# ---------------------------------------------------------------------------------------------

def program_path(word):
    if word.startswith("build/"):
        return os.path.join(BUILD, word[len("build/"):])
    return os.path.join(ROOT, word)


def check_inputs(words, problems):
    for k, word in enumerate(words):
        value = word.split("=", 1)[1] if word.startswith("--") and "=" in word else word
        option = word.split("=", 1)[0] if word.startswith("--") and "=" in word else (words[k - 1] if k else "")
        names_input = option in INPUT_OPTIONS or value.startswith(REPO_FOLDERS) or value.startswith("build/")
        if not names_input or value.startswith("-") or placeholder(value):
            continue
        path = program_path(value) if value.startswith("build/") else os.path.join(ROOT, value)
        if not os.path.exists(path):
            problems.append("%s names %s, which does not exist" % (option or "it", value))


def check_thinlayer(program, words, problems):
    if not words:
        problems.append("thinlayer without a command")
        return
    if words[0] in ("--help", "-h", "--version") and len(words) == 1:
        return
    command, words = words[0], words[1:]
    if command not in ("solve", "study", "verify"):
        problems.append("unknown command '%s'" % command)
        return
    options, _ = thinlayer_options(program, command)
    if command == "study":
        if not words or words[0].startswith("-"):
            problems.append("study without a study name")
            return
        if words[0] not in thinlayer_studies(program):
            problems.append("unknown study '%s'" % words[0])
        words = words[1:]
    seen = set()
    k = 0
    while k < len(words):
        word = words[k]
        name = word.split("=", 1)[0]
        if not name.startswith("--"):
            problems.append("stray argument '%s'" % word)
            k += 1
            continue
        if name not in options:
            problems.append("thinlayer %s has no option %s" % (command, name))
            k += 1
            continue
        if name in seen:
            problems.append("%s given twice" % name)
        seen.add(name)
        if options[name]:  # a value option: its value joined (--x=v) or next, never another option
            if "=" not in word:
                if k + 1 == len(words):
                    problems.append("%s needs a value" % name)
                elif re.match(r"--|-[a-zA-Z]", words[k + 1]):
                    problems.append("%s needs a value, got the option %s" % (name, words[k + 1]))
                else:
                    k += 1
        elif "=" in word:
            problems.append("%s takes no value" % name)
        k += 1


def check_other(argv, words, problems):
    """A program other than thinlayer: its options must be named in its own --help text."""
    _, text = help_text(argv)
    named = set(re.findall(r"--[\w-]+", text)) - {"--help"}
    if not named:
        return  # its help names no option (it has none, or it has no --help): existence only
    for word in words:
        if word.startswith("--"):
            name = word.split("=", 1)[0]
            if name not in named:
                problems.append("%s has no option %s (its --help names %s)" %
                                (os.path.basename(argv[-1]), name, ", ".join(sorted(named))))


def uses_argparse(script):
    with open(script, encoding="utf-8") as f:
        return "argparse" in f.read()


def check_command(text):
    """The problems of one quoted command ([] when it parses and what it names exists)."""
    words = shlex.split(text.replace("[", " ").replace("]", " "))
    while words and (words[0] in LAUNCHERS or words[0].startswith("-") or re.fullmatch(r"\d+", words[0])):
        words = words[1:]
    problems = []
    if words[0] == "/usr/bin/python3":
        words = words[1:]
        if not words:
            return ["python3 without a script"]
    program = program_path(words[0])
    if not os.path.exists(program):
        return ["%s does not exist%s" % (words[0], " (not built?)" if words[0].startswith("build/") else "")]
    if os.path.isdir(program):
        return []  # a folder named in the prose (build/, scripts/)
    check_inputs(words[1:], problems)
    if words[0] == "build/thinlayer":
        check_thinlayer(program, words[1:], problems)
    elif words[0].startswith("build/") or (program.endswith(".py") and uses_argparse(program)):
        # Only programs known to answer --help without doing anything else: the project's build/
        # programs (a help or a usage line) and argparse scripts; a shell script (setup.sh) would run.
        check_other([sys.executable if program.endswith(".py") else program] +
                    ([program] if program.endswith(".py") else []), words[1:], problems)
    return problems


# ---------------------------------------------------------------------------------------------

class DocCommandsTest(unittest.TestCase):
    def test_every_quoted_command_parses_and_its_inputs_exist(self):
        failures, count = [], 0
        for path in documents():
            for number, text in quoted_commands(path):
                count += 1
                for problem in check_command(text):
                    failures.append("%s:%d: %s\n    %s" % (os.path.relpath(path, ROOT), number, problem, text))
        print("%d quoted commands checked in %d files" % (count, len(documents())))
        self.assertGreater(count, 50)  # the extraction itself still finds the manual's commands
        self.assertEqual(failures, [], "\n" + "\n".join(failures))

    def test_the_checker_refuses_what_thinlayer_refuses(self):
        # The checker's own controls: each of these is wrong in one way, and said so.
        wrong = {
            "build/thinlayer solve --scene cases/double_lap/double_lap.json --frobnicate 1": "has no option --frobnicate",
            "build/thinlayer solve --scene cases/no_such/joint.json": "does not exist",
            "build/thinlayer study nonsense --out results/x": "unknown study 'nonsense'",
            "build/thinlayer solve --case bar --eps --json": "needs a value, got the option --json",
            "build/thinlayer solve --case bar --row 1 --row 2": "--row given twice",
            "build/thinlayer solve --json=1 --case bar": "--json takes no value",
            "build/thinlayer frobnicate": "unknown command",
            "build/no_such_program --x 1": "does not exist",
            "/usr/bin/python3 scripts/no_such_script.py": "does not exist",
            "build/thinlayer_scaling --joint cases/double_lap/double_lap.json --frobnicate 1": "has no option --frobnicate",
        }
        for text, expected in wrong.items():
            with self.subTest(text=text):
                problems = check_command(text)
                self.assertTrue(any(expected in p for p in problems), problems)
        for text in ("build/thinlayer solve --scene cases/double_lap/double_lap.json --mode layer --out dl.h5",
                     "mpirun -n 2 build/thinlayer study table3 --out results/table3",
                     "build/thinlayer study validity-map --scene FILE.json --out DIR",
                     "build/thinlayer_scaling --joint cases/double_lap/double_lap.json --sizes 0.5,0.25"):
            with self.subTest(text=text):
                self.assertEqual(check_command(text), [])

    def test_commands_are_found_in_fences_inline_and_across_lines(self):
        import tempfile
        with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as f:
            f.write("text `build/thinlayer solve\n--case bar` more\n```\n"
                    "/usr/bin/python3 scripts/x.py --a 1 \\\n    --b 2   # comment\n"
                    "scripts/setup.sh && build/thinlayer verify --out results/verify\n```\n")
        try:
            found = [text for _, text in quoted_commands(f.name)]
        finally:
            os.unlink(f.name)
        self.assertEqual(sorted(found), sorted(["/usr/bin/python3 scripts/x.py --a 1  --b 2",
                                                "scripts/setup.sh", "build/thinlayer verify --out results/verify",
                                                "build/thinlayer solve --case bar"]))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: test_doc_commands.py BUILD_DIR")
    BUILD = os.path.abspath(sys.argv[1])
    unittest.main(argv=sys.argv[:1], verbosity=2)
