#!/usr/bin/env python3
"""Fails when a file of src/ is longer than 500 lines or a function in it longer than 100: a unit that
long does more than one job.

  check_sizes.py SRC_DIR [--max-file 500] [--max-function 100]

A function is a definition that starts at the left margin (the code is not indented inside its
namespace) and ends at the first line that is a lone closing brace there; its length counts from
its first line to that brace."""
import argparse
import os
import re
import sys

HEAD = re.compile(r'^[A-Za-z_][\w:<>,\s\*&~\[\]]*\(')  # a declarator at the left margin
NOT_FUNCTION = re.compile(r'^(namespace|struct|class|enum|union|using|typedef|extern|static_assert|#|//|template\s*<[^>]*>\s*$)')


def functions(lines):
    """(name line, first, last) of each definition at the left margin, 1-based."""
    i = 0
    while i < len(lines):
        line = lines[i]
        if line and not line[0].isspace() and not NOT_FUNCTION.match(line) and HEAD.match(line):
            j = i
            while j < len(lines) and '{' not in lines[j] and not lines[j].rstrip().endswith(';'):
                j += 1
            if j < len(lines) and '{' in lines[j] and not lines[i].rstrip().endswith(';'):
                if lines[j].rstrip().endswith('}') and j == i:  # a one-line body
                    i += 1
                    continue
                k = j
                while k < len(lines) and lines[k].rstrip() not in ('}', '};'):
                    k += 1
                yield line.strip(), i + 1, k + 1
                i = k + 1
                continue
        i += 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('src')
    parser.add_argument('--max-file', type=int, default=500)
    parser.add_argument('--max-function', type=int, default=100)
    args = parser.parse_args()
    problems = []
    for d, _, files in os.walk(args.src):
        for f in sorted(files):
            if not f.endswith(('.cpp', '.h')):
                continue
            path = os.path.join(d, f)
            with open(path, encoding='utf-8') as text:
                lines = text.read().split('\n')
            if lines and lines[-1] == '':
                lines.pop()
            if len(lines) > args.max_file:
                problems.append(f'{path}: {len(lines)} lines, more than {args.max_file}')
            for name, first, last in functions(lines):
                if last - first + 1 > args.max_function:
                    problems.append(f'{path}:{first}: a function of {last - first + 1} lines, more than '
                                    f'{args.max_function}: {name[:80]}')
    for p in sorted(problems):
        print(f'check_sizes: {p}')
    if problems:
        sys.exit(1)
    print(f'check_sizes: every file of {args.src} within {args.max_file} lines, every function within {args.max_function}')


if __name__ == '__main__':
    main()
