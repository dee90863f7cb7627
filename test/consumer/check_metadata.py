#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Syntax and consistency check of dhmath's ecosystem metadata (run by
test/consumer/run.sh, the "package" stage of tools/check.sh).

  check_metadata.py [source tree]

Reads the settings from include/dhmath/config.h: every
"#ifndef DH_X / #define DH_X <number>" with its range check
("#if (DH_X < a) || (DH_X > b)" or "!= 0 && != 1"), and DH_VERSION_STRING.
Checks, with no YAML or Kconfig library:
  - zephyr/Kconfig parses (config/if/endif/menu blocks, one type per
    option, help text indented) and has, for every DH_X, an option
    DHMATH_X: int with the same range and default, or bool with the
    default y/n for a 0..1 setting; every option but DHMATH is such a one;
  - zephyr/CMakeLists.txt has balanced parentheses and passes every DH_X
    from CONFIG_DHMATH_X;
  - zephyr/module.yml names the module and points at files that exist;
  - library.json is JSON with name, version == DH_VERSION_STRING, existing
    srcDir/includeDir and -fno-math-errno, license Apache-2.0, a git
    repository url, authors with names, and platforms as a list that names
    native, Cortex-M and RISC-V platforms and not atmelavr (AVR would copy
    the tables to RAM);
  - zephyr/module.yml names the licence (in a comment: its schema has no
    licence key);
  - the top-level CMakeLists.txt knows every DH_X as an option.
Exit status 0 when every check holds.
"""
import json
import os
import re
import sys

errors = []


def err(msg):
    errors.append(msg)


def read(root, rel):
    try:
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            return f.read()
    except OSError:
        err("%s: missing" % rel)
        return ""


def header_settings(text):
    """{name: (default, lo, hi)} and the version string."""
    settings = {}
    for m in re.finditer(r"^#ifndef (DH_[A-Z0-9_]+)\n#define \1 ([0-9]+)\n#endif\n", text, re.M):
        name, default = m.group(1), int(m.group(2))
        rng = re.search(r"^#if \(%s < ([0-9]+)\) \|\| \(%s > ([0-9]+)\)" % (name, name), text, re.M)
        boolean = re.search(r"^#if \(%s != 0\) && \(%s != 1\)" % (name, name), text, re.M)
        if rng:
            settings[name] = (default, int(rng.group(1)), int(rng.group(2)))
        elif boolean:
            settings[name] = (default, 0, 1)
        else:
            err("config.h: %s has no range check" % name)
    ver = re.search(r'^#define DH_VERSION_STRING "([0-9]+\.[0-9]+\.[0-9]+)"', text, re.M)
    parts = [re.search(r"^#define DH_VERSION_%s ([0-9]+)" % p, text, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
    if not ver or not all(parts):
        err("config.h: DH_VERSION_MAJOR/MINOR/PATCH/STRING missing")
        return settings, None
    if ver.group(1) != ".".join(p.group(1) for p in parts):
        err("config.h: DH_VERSION_STRING %s does not match the numbers" % ver.group(1))
    return settings, ver.group(1)


def parse_kconfig(text):
    """{name: {"type", "range", "default"}}; syntax errors go to err()."""
    options = {}
    stack = []
    cur = None
    in_help = False
    help_indent = None
    for no, raw in enumerate(text.split("\n"), 1):
        line = raw.rstrip()
        where = "zephyr/Kconfig:%d" % no
        if in_help:
            if not line.strip():
                continue
            indent = len(line) - len(line.lstrip())
            if help_indent is None:
                if indent == 0:
                    err(where + ": empty help text")
                help_indent = indent
            if indent >= help_indent and indent > 0:
                continue
            in_help = False
        body = line.split("#", 1)[0].strip() if not line.lstrip().startswith("help") else line.strip()
        if not body:
            continue
        words = body.split(None, 1)
        kw, rest = words[0], (words[1] if len(words) > 1 else "")
        if kw in ("config", "menuconfig"):
            if not re.fullmatch(r"[A-Z][A-Z0-9_]*", rest):
                err(where + ": bad symbol name '%s'" % rest)
            if rest in options:
                err(where + ": %s defined twice" % rest)
            cur = options.setdefault(rest, {"type": None, "range": None, "default": None})
        elif kw in ("bool", "int", "hex", "string", "tristate"):
            if cur is None:
                err(where + ": type outside a config entry")
            elif cur["type"] is not None:
                err(where + ": second type")
            else:
                cur["type"] = kw
            if rest and not re.fullmatch(r'"[^"]*"', rest):
                err(where + ": prompt must be a quoted string")
        elif kw == "range":
            m = re.fullmatch(r"(-?[0-9]+) (-?[0-9]+)", rest)
            if cur is None or not m:
                err(where + ": bad range")
            else:
                cur["range"] = (int(m.group(1)), int(m.group(2)))
        elif kw == "default":
            if cur is None or not rest:
                err(where + ": bad default")
            else:
                cur["default"] = rest
        elif kw in ("depends", "select", "imply"):
            if cur is None or not rest:
                err(where + ": bad " + kw)
        elif kw == "help":
            if cur is None or rest:
                err(where + ": bad help")
            in_help, help_indent = True, None
        elif kw in ("if", "menu"):
            if not rest:
                err(where + ": %s without argument" % kw)
            stack.append(kw)
            cur = None
        elif kw in ("endif", "endmenu"):
            if not stack or stack[-1] != kw[3:]:
                err(where + ": unbalanced " + kw)
            else:
                stack.pop()
            cur = None
        elif kw in ("source", "rsource", "orsource", "comment", "mainmenu"):
            cur = None
        else:
            err(where + ": unknown keyword '%s'" % kw)
    if stack:
        err("zephyr/Kconfig: unclosed " + ", ".join(stack))
    for name, o in options.items():
        if o["type"] is None:
            err("zephyr/Kconfig: %s has no type" % name)
    return options


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    settings, version = header_settings(read(root, "include/dhmath/config.h"))
    if len(settings) < 5:
        err("config.h: only %d settings found" % len(settings))

    kconf = parse_kconfig(read(root, "zephyr/Kconfig"))
    if "DHMATH" not in kconf or kconf["DHMATH"]["type"] != "bool":
        err("zephyr/Kconfig: no bool DHMATH")
    for name, (default, lo, hi) in sorted(settings.items()):
        kname = "DHMATH_" + name[3:]
        o = kconf.get(kname)
        if o is None:
            err("zephyr/Kconfig: no option %s for %s" % (kname, name))
            continue
        if (lo, hi) == (0, 1):
            if o["type"] != "bool" or o["default"] != ("y" if default else "n"):
                err("zephyr/Kconfig: %s must be bool, default %s" % (kname, "y" if default else "n"))
        elif o["type"] != "int" or o["range"] != (lo, hi) or o["default"] != str(default):
            err("zephyr/Kconfig: %s must be int, range %d %d, default %d (as %s)" % (kname, lo, hi, default, name))
    for kname in kconf:
        if kname != "DHMATH" and "DH_" + kname[7:] not in settings:
            err("zephyr/Kconfig: %s maps to no setting of config.h" % kname)

    zcm = read(root, "zephyr/CMakeLists.txt")
    code = re.sub(r"#.*", "", zcm)
    if code.count("(") != code.count(")"):
        err("zephyr/CMakeLists.txt: unbalanced parentheses")
    for name in settings:
        short = name[3:]
        direct = "%s=${CONFIG_DHMATH_%s}" % (name, short) in code
        via_bool = re.search(r"\b%s=\$\{_dh_%s\}" % (name, short), code) and "CONFIG_DHMATH_${_dh_b}" in code \
            and re.search(r"foreach\(_dh_b [A-Z_ ]*\b%s\b" % short, code)
        if not (direct or via_bool):
            err("zephyr/CMakeLists.txt: %s is not set from CONFIG_DHMATH_%s" % (name, short))

    mod = read(root, "zephyr/module.yml")
    kv = {}
    section = ""
    for no, raw in enumerate(mod.split("\n"), 1):
        line = raw.split("#", 1)[0].rstrip()
        if not line:
            continue
        m = re.fullmatch(r"( *)([a-z_-]+):(?: (\S.*))?", line)
        if not m or "\t" in raw:
            err("zephyr/module.yml:%d: not a 'key: value' line" % no)
            continue
        if m.group(1) == "":
            section = m.group(2)
            kv[section] = m.group(3)
        else:
            kv[section + "." + m.group(2)] = m.group(3)
    if kv.get("name") != "dhmath":
        err("zephyr/module.yml: name is not dhmath")
    cm = kv.get("build.cmake")
    if not cm or not os.path.isfile(os.path.join(root, cm, "CMakeLists.txt")):
        err("zephyr/module.yml: build.cmake does not name a directory with a CMakeLists.txt")
    if not re.search(r"^#.*\bApache-2\.0\b", mod, re.M):
        err("zephyr/module.yml: no comment naming the licence (Apache-2.0)")
    kc = kv.get("build.kconfig")
    if not kc or not os.path.isfile(os.path.join(root, kc)):
        err("zephyr/module.yml: build.kconfig does not name a file")

    try:
        lj = json.loads(read(root, "library.json"))
    except ValueError as e:
        err("library.json: %s" % e)
        lj = {}
    if lj:
        if lj.get("name") != "dhmath":
            err("library.json: name is not dhmath")
        if lj.get("version") != version:
            err("library.json: version %s, config.h says %s" % (lj.get("version"), version))
        build = lj.get("build", {})
        for key in ("srcDir", "includeDir"):
            if not os.path.isdir(os.path.join(root, build.get(key, "?"))):
                err("library.json: build.%s is not a directory" % key)
        if "-fno-math-errno" not in build.get("flags", []):
            err("library.json: build.flags lacks -fno-math-errno")
        if lj.get("license") != "Apache-2.0":
            err("library.json: license is not Apache-2.0")
        repo = lj.get("repository")
        if not isinstance(repo, dict) or repo.get("type") != "git" or not str(repo.get("url", "")).startswith("https://"):
            err("library.json: repository is not {type: git, url: https://...}")
        authors = lj.get("authors")
        if not isinstance(authors, list) or not authors or not all(isinstance(a, dict) and a.get("name")
                                                                    for a in authors):
            err("library.json: authors is not a list of {name: ...}")
        plat = lj.get("platforms")
        if not isinstance(plat, list):
            err("library.json: platforms is not a list")
        else:
            for need in ("native", "ststm32", "sifive"):
                if need not in plat:
                    err("library.json: platforms lacks %s" % need)
            for bad in ("*", "atmelavr", "atmelmegaavr"):
                if bad in plat:
                    err("library.json: platforms names %s" % bad)

    top = read(root, "CMakeLists.txt")
    known = re.search(r"set\(_dh_known([^)]*)\)", top)
    for name in settings:
        if not known or name not in known.group(1).split():
            err("CMakeLists.txt: %s is not a known option" % name)

    for e in errors:
        print("METADATA: " + e)
    if not errors:
        print("check_metadata: %d settings (%s), version %s: Kconfig, zephyr CMake, module.yml, library.json agree"
              % (len(settings), " ".join(sorted(settings)), version))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
