#!/usr/bin/env python3
"""Removes the answers that live in shared code from a handout (./wb handout, issue 18).

handout_strip.py DIR LIST: LIST (labs/handout_strip.txt) has one line per cut, tab-separated:
  FILE  body   START [REPLACEMENT]  the function whose definition starts with the line START:
                                    its body becomes REPLACEMENT (\\n for a new line; default:
                                    a throw saying why)
  FILE  decl   START                the declaration starting with START, through its '};'
  FILE  lines  START  END           the lines from START through END (comments; in a .po
                                    catalogue a msgid through its msgstr; in a .md page)
START/END match the beginning of a line after its indentation. A cut that matches nothing is
an error: the list must follow the code.
"""
import sys


def block_end(text, open_pos):
    depth = 0
    for i in range(open_pos, len(text)):
        if text[i] == '{':
            depth += 1
        elif text[i] == '}':
            depth -= 1
            if depth == 0:
                return i
    raise ValueError('unbalanced braces')


def line_start(text, start):
    pos = 0
    for line in text.splitlines(keepends=True):
        if line.lstrip().startswith(start):
            return pos
        pos += len(line)
    return -1


def main():
    root, listing = sys.argv[1], sys.argv[2]
    failed = False
    for n, raw in enumerate(open(listing, encoding='utf-8'), 1):
        raw = raw.rstrip('\n')
        if not raw.strip() or raw.startswith('#'):
            continue
        f = raw.split('\t')
        path, mode, start = f[0], f[1], f[2]
        full = f'{root}/{path}'
        text = open(full, encoding='utf-8').read()
        at = line_start(text, start)
        if at < 0:
            print(f'{listing}:{n}: {path}: no line starts with {start!r}', file=sys.stderr)
            failed = True
            continue
        if mode == 'body':
            if len(f) > 3:  # an explicit body: START need not hold the whole parameter list
                repl = f[3].replace('\\n', '\n')
            else:
                name = start.split('(')[0].split()[-1]
                params = start[start.index('(') + 1:start.rindex(')')]
                unused = ''.join(f'    (void){p.split()[-1].lstrip("&*")};\n'
                                 for p in params.split(',') if p.strip())
                repl = (f'\n{unused}    throw std::logic_error("{name}: not in the handout: it is a graded task");\n')
                if '<stdexcept>' not in text:
                    text = '#include <stdexcept> // the handout cut answers here: they throw\n' + text
            # Helpers only the cut code used are left unused.
            if '#pragma GCC diagnostic ignored "-Wunused-function"' not in text:
                text = '#pragma GCC diagnostic ignored "-Wunused-function" // the handout cut answers here\n' + text
            open_pos = text.index('{', line_start(text, start))
            close = block_end(text, open_pos)
            text = text[:open_pos + 1] + repl + text[close:]
        elif mode == 'decl':
            open_pos = text.index('{', at)
            close = block_end(text, open_pos)
            end = text.index(';', close) + 1
            text = text[:at] + '// (removed from the handout: an answer)' + text[end:]
        elif mode == 'lines':
            end_at = line_start(text[at:], f[3])
            if end_at < 0:
                print(f'{listing}:{n}: {path}: no end line {f[3]!r}', file=sys.stderr)
                failed = True
                continue
            end = text.index('\n', at + end_at) + 1
            note = '(removed from the handout: it described an answer)'
            if path.endswith('.po'):
                note = f'# {note}'  # a catalogue's comments start with #
            elif path.endswith('.md'):
                note = f'<!-- {note} -->'
            else:
                note = f'// {note}'
            text = text[:at] + note + '\n' + text[end:]
        else:
            print(f'{listing}:{n}: unknown mode {mode}', file=sys.stderr)
            failed = True
            continue
        open(full, 'w', encoding='utf-8').write(text)
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
