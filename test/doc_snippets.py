#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""doc_snippets.py - every C snippet of README.md and docs/*.md compiles
against the built library, runs with status 0 and, when valgrind is
installed, runs valgrind-clean.

    python3 test/doc_snippets.py --root ROOT --cc CC --lib LIBDHMATH.a
        --out DIR [--includes 'DIR@@DIR'] [--defines 'A=1@@B=2'] [--cli DHMATH]
        [--cflags 'FLAG@@FLAG'] [--no-valgrind]

Each ```c fence is one of:
  * a whole program: it defines main(); compiled as it is;
  * a fragment: its first line is '/* fragment: WRAPPER ... */', WRAPPER a
    C file under the root holding the line '/* @SNIPPET@ */' where the
    fragment goes (the prose of the doc says what surrounds it). A line
    '/* @GEN@ ROBOT.dh NAME */' of the wrapper adds the source written by
    'dhmath gen ROBOT.dh NAME' (needs --cli) to the program.
Any other ```c fence fails the test, and so does a C fence under another
name (```h, ```c99 ...), a wrapper under test/snippets/ that no fragment
uses, an unclosed fence, or a compiler warning (-Werror).
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

WARN = ['-std=c99', '-pedantic', '-Wall', '-Wextra', '-Wshadow', '-Wundef', '-Werror', '-g', '-O1']
FENCE = re.compile(r'^(\s*)```\s*([A-Za-z0-9_+-]*)\s*$')
FRAGMENT = re.compile(r'^/\* fragment: (\S+?)[,:;]?\s.*\*/\s*$|^/\* fragment: (\S+?)\s*\*/\s*$')
MAIN = re.compile(r'\bint\s+main\s*\(')
SLOT = '/* @SNIPPET@ */'
OTHER_C = ('h', 'c99', 'c11', 'cc', 'ansi-c')   # C under another name: an error, never skipped
GEN = re.compile(r'^\s*/\* @GEN@ (\S+) ([A-Za-z_][A-Za-z0-9_]*) \*/\s*$', re.M)


def snippets(path):
    """[(first line number, text)] of the ```c fences of a Markdown file"""
    out, cur, start, lang = [], None, 0, None
    with open(path, encoding='utf-8') as f:
        for no, line in enumerate(f, 1):
            m = FENCE.match(line.rstrip('\n'))
            if cur is None:
                if m:
                    cur, start, lang = [], no, m.group(2).lower()
            elif m and m.group(2) == '':
                if lang == 'c':
                    out.append((start, ''.join(cur)))
                elif lang in OTHER_C:
                    raise SystemExit('%s:%d: a ```%s fence: C snippets are ```c (or another language, '
                                     'not tested here)' % (path, start, lang))
                cur = None
            else:
                cur.append(line)
    if cur is not None:
        raise SystemExit('%s:%d: fence not closed' % (path, start))
    return out


def run(cmd, what, timeout=120):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)
    if p.returncode != 0:
        out = p.stdout if len(p.stdout) <= 6000 else p.stdout[:6000] + '\n[... %d more characters]' % (len(p.stdout) - 6000)
        return '%s failed (status %d): %s\n%s' % (what, p.returncode, ' '.join(cmd), out)
    return None


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument('--root', required=True)
    ap.add_argument('--cc', required=True)
    ap.add_argument('--lib', required=True)
    ap.add_argument('--out', required=True)
    ap.add_argument('--includes', default='')
    ap.add_argument('--defines', default='')
    ap.add_argument('--cli')
    ap.add_argument('--cflags', default='', help="the build's own compile and link flags, '@@'-separated")
    ap.add_argument('--no-valgrind', action='store_true', help='a sanitizer build: the sanitizers check instead')
    a = ap.parse_args(argv[1:])
    root = os.path.abspath(a.root)
    incs = [d for d in a.includes.split('@@') if d] or [os.path.join(root, 'include')]
    defs = [d for d in a.defines.split('@@') if d]
    flags = WARN + [f for f in a.cflags.split('@@') if f] + ['-I' + d for d in incs] + ['-D' + d for d in defs]
    valgrind = None if a.no_valgrind else shutil.which('valgrind')
    os.makedirs(a.out, exist_ok=True)

    docs = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))
    failures, used, count = [], set(), 0
    for doc in docs:
        rel = os.path.relpath(doc, root)
        for line, text in snippets(doc):
            count += 1
            name = '%s_%d' % (re.sub(r'[^A-Za-z0-9]', '_', rel), line)
            where = '%s:%d' % (rel, line)
            first = text.split('\n', 1)[0]
            m = FRAGMENT.match(first)
            extra = []
            if m:
                wrapper = os.path.normpath(os.path.join(root, m.group(1) or m.group(2)))
                used.add(wrapper)
                if not os.path.isfile(wrapper):
                    failures.append('%s: fragment wrapper %s does not exist' % (where, wrapper))
                    continue
                with open(wrapper, encoding='utf-8') as f:
                    wtext = f.read()
                if wtext.count(SLOT) != 1:
                    failures.append('%s: %s must hold the line %s once' % (where, wrapper, SLOT))
                    continue
                after = wtext[:wtext.index(SLOT)].count('\n') + 2   # the wrapper's line after the slot
                source = wtext.replace(SLOT, '#line %d "%s"\n%s#line %d "%s"' % (line + 1, doc, text, after, wrapper))
                for gm in GEN.finditer(wtext):
                    if not a.cli:
                        failures.append('%s: %s needs dhmath gen (no --cli)' % (where, wrapper))
                        break
                    gsrc = os.path.join(a.out, '%s_%s.c' % (name, gm.group(2)))
                    with open(gsrc, 'w', encoding='utf-8') as g:
                        p = subprocess.run([a.cli, 'gen', os.path.join(root, gm.group(1)), gm.group(2)],
                                           stdout=g, stderr=subprocess.PIPE, text=True)
                    if p.returncode != 0:
                        failures.append('%s: dhmath gen %s failed: %s' % (where, gm.group(1), p.stderr))
                    extra.append(gsrc)
                kind = 'fragment in ' + os.path.relpath(wrapper, root)
            elif MAIN.search(text):
                source = '#line %d "%s"\n%s' % (line + 1, doc, text)
                kind = 'whole program'
            else:
                failures.append('%s: a ```c block that is neither a whole program (main) nor a fragment '
                                '(first line /* fragment: WRAPPER ... */)' % where)
                continue
            src = os.path.join(a.out, name + '.c')
            exe = os.path.join(a.out, name)
            with open(src, 'w', encoding='utf-8') as f:
                f.write(source)
            err = run([a.cc] + flags + [src] + extra + [a.lib, '-o', exe], 'compile')
            if not err:
                err = run([exe], 'run')
            if not err and valgrind:
                err = run([valgrind, '-q', '--error-exitcode=1', '--leak-check=full', exe], 'valgrind', 600)
            print('%s: %s: %s' % (where, kind, 'FAILED' if err else 'ok' + (' (valgrind clean)' if valgrind else '')))
            if err:
                failures.append('%s: %s' % (where, err))
    for w in sorted(glob.glob(os.path.join(root, 'test', 'snippets', '*.c'))):
        if os.path.normpath(w) not in used:
            failures.append('%s: no fragment uses this wrapper' % os.path.relpath(w, root))
    if count == 0:
        failures.append('no ```c block found in README.md and docs/*.md')
    if not valgrind:
        print('the snippets ran without valgrind (%s)' % ('--no-valgrind' if a.no_valgrind else 'not installed'))
    for f in failures:
        print('FAIL ' + f)
    print('%d C snippets, %d failures' % (count, len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
