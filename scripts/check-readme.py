#!/usr/bin/env python3
"""Keeps the README and docs/ true to the tool.

  check-readme.py links SOURCE_DIR
      Every relative link and image in README.md and docs/*.md points to an
      existing file inside the repository (and, with #anchor, to a heading of
      that page); the README names nothing outside the repository.

  check-readme.py run SOURCE_DIR FOURBAR [--readme FILE]
      Runs the README's commands in a temporary copy of data/ with FOURBAR on
      PATH and checks the output excerpts the README shows.

How the README marks its blocks (an HTML comment on the line before the
fence, invisible when rendered):
  <!-- check: run -->          a shell block run with `bash -eo pipefail`; it
                                must exit 0
  <!-- check: output -->        an excerpt of the previous run block's output
                                (stdout and stderr): every line must appear
                                inside an output line (blank runs collapsed);
                                "…" stands for anything
  <!-- check: file PATH -->     the block's text is written to PATH first
  <!-- check: skip -->          a shell block not run (needs root, a network,
                                or a full build), with the reason after it
The first fenced block is the README's opening pair of commands: the second
line must be the one `.ci/run` runs, the `fourbar` part of the first is run.
Every other sh/bash/console block must carry a mark, so none can go stale
unnoticed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\S*)\s*$")
MARK = re.compile(r"^<!--\s*check:\s*(run|output|skip|file)\s*(.*?)\s*-->\s*$")
SHELL = {"sh", "bash", "shell", "console"}


def fail(msg):
    print(f"check-readme: {msg}", file=sys.stderr)
    return 1


def blocks(path):
    """Fenced blocks: (line number, info, mark, mark argument, text)."""
    lines = open(path, encoding="utf-8").read().split("\n")
    out, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, info = i, m.group(1)
        mark = MARK.match(lines[i - 1]) if i > 0 else None
        j = i + 1
        while j < len(lines) and lines[j] != "```":
            j += 1
        if j == len(lines):
            raise SystemExit(fail(f"{path}:{start + 1}: fenced block never closed"))
        out.append((start + 1, info, mark.group(1) if mark else None,
                    mark.group(2) if mark else "", "\n".join(lines[start + 1:j]) + "\n"))
        i = j + 1
    return out


# ---- links ----------------------------------------------------------------

def slug(heading):
    """GitHub's anchor for a heading."""
    s = re.sub(r"`|\*\*|\*", "", heading.strip().lower())
    s = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", s)
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(path):
    found, seen = set(), {}
    in_code = False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            in_code = not in_code
        if in_code:
            continue
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            found.add(s if n == 0 else f"{s}-{n}")
    return found


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def check_links(src):
    src = os.path.realpath(src)
    pages = [os.path.join(src, "README.md")]
    pages += sorted(os.path.join(src, "docs", f) for f in os.listdir(os.path.join(src, "docs"))
                    if f.endswith(".md"))
    errors = 0
    for page in pages:
        rel_page = os.path.relpath(page, src)
        text = open(page, encoding="utf-8").read()
        no_code = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in LINK.findall(no_code):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto: — not a file of the repository
            path, _, anchor = target.partition("#")
            dest = os.path.realpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not (dest == src or dest.startswith(src + os.sep)):
                errors += fail(f"{rel_page}: link '{target}' points outside the repository")
            elif not os.path.exists(dest):
                errors += fail(f"{rel_page}: link '{target}': {os.path.relpath(dest, src)} does not exist")
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                errors += fail(f"{rel_page}: link '{target}': no heading '#{anchor}' in "
                               f"{os.path.relpath(dest, src)}")
        if rel_page == "README.md":
            for n, line in enumerate(text.split("\n"), 1):
                if re.search(r"\.\./shared|\.\./\.\.|(^|[\s`(\"'])/(work|home|tmp|root)/", line):
                    errors += fail(f"README.md:{n}: names a path outside the repository: {line.strip()}")
    print(f"check-readme: links: {len(pages)} pages checked, {errors} problem(s)")
    return 1 if errors else 0


# ---- running the README -----------------------------------------------------

def excerpt_found(excerpt, output):
    """The first excerpt line found in no output line ("…" = anything), or None.

    Lines are matched with runs of blanks collapsed; not in order, since
    stderr and stdout of one block interleave differently from run to run."""
    norm = lambda s: " ".join(s.split())
    out_lines = [norm(l) for l in output.split("\n")]
    for want in excerpt.split("\n"):
        want = norm(want)
        if not want or want in ("…", "..."):
            continue
        pattern = ".*".join(re.escape(p.strip()) for p in want.split("…"))
        if not any(re.search(pattern, l) for l in out_lines):
            return want
    return None


def run_block(script, cwd, env, where):
    print(f"check-readme: {where}: running\n" + "".join(f"    {l}\n" for l in script.strip().split("\n")),
          flush=True)
    p = subprocess.run(["bash", "-eo", "pipefail", "-c", script], cwd=cwd, env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=900)
    return p.returncode, p.stdout


def check_run(src, fourbar, readme):
    src = os.path.realpath(src)
    fourbar = os.path.realpath(fourbar)
    ci = open(os.path.join(src, ".ci", "run"), encoding="utf-8").read()
    all_blocks = blocks(readme)
    if not all_blocks:
        return fail(f"{readme}: no fenced block")
    line, _, _, _, top = all_blocks[0]
    top_lines = top.strip("\n").split("\n")
    if len(top_lines) != 2:
        return fail(f"{readme}:{line}: the first block must hold the two opening commands")
    if top_lines[1] not in ci:
        return fail(f"{readme}:{line + 2}: .ci/run does not run the README's second command "
                    f"'{top_lines[1]}'")
    m = re.search(r"\./build/cli/fourbar (.*)$", top_lines[0])
    if not m:
        return fail(f"{readme}:{line + 1}: the first command does not run ./build/cli/fourbar")
    runs = [(line + 1, "fourbar " + m.group(1))]

    errors = 0
    with tempfile.TemporaryDirectory(prefix="fourbar-readme-") as work:
        shutil.copytree(os.path.join(src, "data"), os.path.join(work, "data"))
        env = dict(os.environ)
        env["PATH"] = os.path.dirname(fourbar) + os.pathsep + env.get("PATH", "")
        env.pop("FOURBAR_NO_PROGRESS", None)
        last_output, last_where = None, None
        steps = [(runs[0][0], "sh", "run", "", runs[0][1] + "\n")] + all_blocks[1:]
        n_run = n_out = 0
        for line, info, mark, arg, text in steps:
            where = f"{os.path.basename(readme)}:{line}"
            if mark is None:
                if info in SHELL:
                    errors += fail(f"{where}: a {info} block without a <!-- check: ... --> mark")
                continue
            if mark == "skip":
                continue
            if mark == "file":
                dest = os.path.join(work, arg)
                os.makedirs(os.path.dirname(dest), exist_ok=True)
                open(dest, "w", encoding="utf-8").write(text)
                continue
            if mark == "run":
                script = text.replace("./build/cli/fourbar", fourbar)
                rc, last_output = run_block(script, work, env, where)
                last_where = where
                n_run += 1
                if rc != 0:
                    errors += fail(f"{where}: exited {rc}; output:\n{last_output}")
                continue
            if mark == "output":
                n_out += 1
                if last_output is None:
                    errors += fail(f"{where}: an output block before any run block")
                    continue
                missing = excerpt_found(text, last_output)
                if missing is not None:
                    errors += fail(f"{where}: the output of {last_where} no longer shows\n    {missing}\n"
                                   f"  it printed:\n{last_output}")
        print(f"check-readme: {n_run} command blocks run, {n_out} output excerpts checked, "
              f"{errors} problem(s)")
    return 1 if errors else 0


def main(argv):
    if len(argv) >= 2 and argv[0] == "links":
        return check_links(argv[1])
    if len(argv) >= 3 and argv[0] == "run":
        readme = os.path.join(argv[1], "README.md")
        if len(argv) == 5 and argv[3] == "--readme":
            readme = argv[4]
        return check_run(argv[1], argv[2], readme)
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
