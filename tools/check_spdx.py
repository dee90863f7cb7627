#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""check_spdx.py - every source, header, script and CMake file of the source
tree carries 'SPDX-License-Identifier: Apache-2.0' in its first three lines.

    python3 tools/check_spdx.py [ROOT]

Walks ROOT (default: the folder above tools/), skipping build folders, .git
and the fuzz corpora (binary inputs). Prints each file that lacks the line
and exits 1 when there is one, 0 otherwise.
"""
import os
import sys

TAG = 'SPDX-License-Identifier: Apache-2.0'
SUFFIXES = ('.c', '.h', '.cpp', '.inc', '.ld', '.cmake', '.txt', '.sh', '.py',
            '.yml', '.in', '.dh', '.dict')
NAMES = ('Makefile', 'Kconfig', '.clang-tidy', '.gitignore', 'Doxyfile', 'run')
SKIP_DIRS = ('.git', 'corpus')


def wanted(name):
    return name.endswith(SUFFIXES) or name in NAMES


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
    missing = []
    checked = 0
    for top, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith('build'))
        for name in sorted(files):
            if not wanted(name):
                continue
            path = os.path.join(top, name)
            with open(path, encoding='utf-8', errors='replace') as fh:
                head = [fh.readline() for _ in range(3)]
            checked += 1
            if not any(TAG in line for line in head):
                missing.append(os.path.relpath(path, root))
    for path in missing:
        print('check_spdx: %s lacks "%s" in its first three lines' % (path, TAG))
    print('check_spdx: %d files checked, %d without the licence line' % (checked, len(missing)))
    return 1 if missing or checked == 0 else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
