#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A man page and what it documents cannot drift apart.

  check_man.py program PAGE BINARY
      every option (and command) BINARY --help prints has an entry in PAGE
      (a .TP tag), and every option PAGE mentions anywhere is in --help;
      --help must exit 0.
  check_man.py config PAGE CONFIG_SOURCE BINARY
      every [section] key of the config table in CONFIG_SOURCE
      (firmware/program/sw_config.c) has an entry under its .SS [section] in PAGE,
      and every entry there is in the table; every option PAGE mentions is
      in BINARY --help.
  check_man.py table PAGE INI_PAGE DUMP
      seamwalk's option table (DUMP: tests/option_table_dump.c's program)
      against seamwalk(1) PAGE and seamwalk.ini(5) INI_PAGE: every option
      but the tests' has an entry tagged with its name and argument, which
      states its range and "default D" as the table has them; every config
      key an option names states the same range and default in its entry.
All also render PAGE with `man --warnings -l` at 80 columns: any warning,
or a non-zero exit, fails. Exit 0 when all holds, 1 naming each difference.
"""
import os
import re
import subprocess
import sys

# An option: -x or --word, not inside a word and not an alternative after
# '|' (--up x|y|z|-x|-y|-z names values, not options).
OPTION = re.compile(r"(?<![\w|.-])(--?[a-zA-Z][\w-]*)")


def plain(roff_line):
    """A roff line's text: escapes for '-' made plain, font changes dropped."""
    s = roff_line.replace("\\-", "-").replace("\\&", "")
    s = re.sub(r"\\f(\[[^]]*\]|.)", "", s)
    return s.replace('"', " ")


def read_page(path):
    """(tags, text): the .TP tag lines as (section, subsection, plain text)
    and the page's plain text without comments."""
    tags, text = [], []
    section = subsection = ""
    lines = open(path, encoding="utf-8").read().split("\n")
    for i, line in enumerate(lines):
        if line.startswith('.\\"'):
            continue
        if line.startswith(".SH "):
            section, subsection = plain(line[4:]).strip(), ""
        elif line.startswith(".SS "):
            subsection = plain(line[4:]).strip()
        elif line.strip() == ".TP" and i + 1 < len(lines):
            tag = re.sub(r"^\.(B|I|BI|IB|BR|RB|IR|RI)\s+", "", lines[i + 1])
            tags.append((section, subsection, plain(tag).strip()))
        text.append(plain(re.sub(r"^\.[A-Z]+\s*", "", line)))
    return tags, "\n".join(text)


def read_entries(path):
    """{(section, subsection, first word of the tag): (tag, body)}: each .TP
    entry's plain tag and its text up to the next entry or heading, blanks
    run together."""
    entries, section, subsection = {}, "", ""
    lines = open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith(".SH "):
            section, subsection = plain(line[4:]).strip(), ""
        elif line.startswith(".SS "):
            subsection = plain(line[4:]).strip()
        elif line.strip() == ".TP" and i + 1 < len(lines):
            tag = plain(re.sub(r"^\.(B|I|BI|IB|BR|RB|IR|RI)\s+", "", lines[i + 1])).split()
            body, i = [], i + 2
            while i < len(lines) and not re.match(r"\.(TP|SS|SH|PP|IP)\b", lines[i]):
                if not lines[i].startswith('.\\"'):
                    body.append(plain(re.sub(r"^\.[A-Z]+\s*", "", lines[i])))
                i += 1
            if tag:
                entries[(section, subsection, tag[0])] = (tag, " ".join(" ".join(body).split()))
            continue
        i += 1
    return entries


def read_table(dump):
    """The option table's rows as dicts, from option_table_dump."""
    out = subprocess.run([dump], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"FAIL: {dump} exited {out.returncode}: {out.stderr.strip()}")
    fields = ("name", "arg", "range", "default", "section", "key", "kind")
    rows = [dict(zip(fields, [None if f == "-" else f for f in line.split("\t")]))
            for line in out.stdout.splitlines()]
    if len(rows) < 20 or any(len(r) != len(fields) for r in rows):
        sys.exit(f"FAIL: {dump}: {len(rows)} rows, not the table's form")
    return rows


def states(where, body, row):
    """What the entry's text lacks of the row's range and default."""
    fails = []
    if row["range"] and row["range"] not in body:
        fails.append(f"FAIL: {where}: no range {row['range']} (the option table's)")
    if row["default"] and f"default {row['default']}" not in body:
        fails.append(f"FAIL: {where}: no 'default {row['default']}' (the option table's)")
    return fails


def check_table(page, ini_page, dump):
    options = {(s, t): e for (s, _, t), e in read_entries(page).items() if s == "OPTIONS"}
    keys = {(sub, t): e for (s, sub, t), e in read_entries(ini_page).items() if s == "SECTIONS"}
    rows = [r for r in read_table(dump) if r["kind"] is None]
    fails = []
    for row in rows:
        entry = options.get(("OPTIONS", row["name"]))
        if not entry:
            fails.append(f"FAIL: {page}: no entry for {row['name']}")
            continue
        tag, body = entry
        arg = " ".join(tag[1:]) or None
        if arg != row["arg"]:
            fails.append(f"FAIL: {page}: {row['name']} takes '{arg}', the table '{row['arg']}'")
        fails += states(f"{page}: {row['name']}", body, row)
        if not row["key"]:
            continue
        entry = keys.get((f"[{row['section']}]", row["key"]))
        where = f"{ini_page}: [{row['section']}] {row['key']}"
        fails += [f"FAIL: {where}: no entry"] if not entry else states(where, entry[1], row)
    fails += check_render(ini_page)
    return fails, len(rows)


def run_help(binary):
    out = subprocess.run([binary, "--help"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"FAIL: {binary} --help exited {out.returncode}: {out.stderr.strip()}")
    return out.stdout


def help_words(binary):
    """The options --help prints, and the commands its usage lines name."""
    text = run_help(binary)
    name = os.path.basename(binary)
    options = set(OPTION.findall(text))
    commands = set(re.findall(r"^(?:usage:)?\s+\S*" + re.escape(name) + r" ([a-z][\w-]*)",
                              text, re.M))
    return options, commands


def page_words(tags):
    """The options the page's entries document, and its COMMANDS entries."""
    options, commands = set(), set()
    for section, _, tag in tags:
        options |= set(OPTION.findall(tag))
        if section == "COMMANDS" and tag.split():
            commands.add(tag.split()[0])
    return options, commands


def differences(what, wanted, have, where_missing):
    return [f"FAIL: {what} '{w}' has no entry in {where_missing}" for w in sorted(wanted - have)]


def check_program(page, binary):
    tags, text = read_page(page)
    help_options, help_commands = help_words(binary)
    man_options, man_commands = page_words(tags)
    name = os.path.basename(binary)
    fails = differences(f"{name} --help's option", help_options, man_options, page)
    fails += differences(f"{name} --help's command", help_commands, man_commands, page)
    fails += differences(f"{page}'s option", set(OPTION.findall(text)), help_options,
                         f"{name} --help")
    fails += differences(f"{page}'s command", man_commands, help_commands, f"{name} --help")
    return fails, len(help_options) + len(help_commands)


def config_keys(source):
    """(section, key) of every row of the config tables in sw_config.c."""
    text = open(source, encoding="utf-8").read()
    keys = set(re.findall(r'\{"(\w+)", "(\w+)", K_[A-Z]+', text))
    keys |= {("gamepad", k) for k in re.findall(r'PAD_BUTTON\("(\w+)", \d+\)', text)}
    if len(keys) < 10 or not {s for s, _ in keys} >= {"display", "pack", "gpio"}:
        sys.exit(f"FAIL: {source}: found only {sorted(keys)}; has the table's form changed?")
    return keys


def check_config(page, source, binary):
    tags, text = read_page(page)
    documented = set()
    for section, subsection, tag in tags:
        heading = re.match(r"\[(\w+)", subsection)
        if section == "SECTIONS" and heading and tag.split():
            documented.add((heading.group(1), tag.split()[0]))
    table = config_keys(source)
    show = lambda keys: {f"[{s}] {k}" for s, k in keys}
    fails = differences("config key", show(table), show(documented), page)
    fails += differences(f"{page}'s key", show(documented), show(table), source)
    help_options, _ = help_words(binary)
    fails += differences(f"{page}'s option", set(OPTION.findall(text)), help_options,
                         f"{os.path.basename(binary)} --help")
    return fails, len(table)


def check_render(page):
    env = dict(os.environ, MANWIDTH="80", LC_ALL="C.UTF-8", MAN_KEEP_FORMATTING="")
    out = subprocess.run(["man", "--warnings", "-l", page], capture_output=True, text=True,
                         env=env)
    if out.returncode != 0 or out.stderr.strip() or not out.stdout.strip():
        return [f"FAIL: man --warnings -l {page}: exit {out.returncode}: {out.stderr.strip()}"]
    return []


def main(argv):
    if len(argv) == 4 and argv[1] == "program":
        fails, count = check_program(argv[2], argv[3])
    elif len(argv) == 5 and argv[1] == "config":
        fails, count = check_config(argv[2], argv[3], argv[4])
    elif len(argv) == 5 and argv[1] == "table":
        fails, count = check_table(argv[2], argv[3], argv[4])
    else:
        sys.exit(__doc__)
    fails += check_render(argv[2])
    for f in fails:
        print(f)
    checked = "options held to the table" if argv[1] == "table" else "entries checked both ways"
    print(f"{os.path.basename(argv[2])}: {count} {checked}, {len(fails)} differences")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
