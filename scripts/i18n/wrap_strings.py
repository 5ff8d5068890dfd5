#!/usr/bin/env python3
"""One-off helper (issue 17): wraps the string literals of ImGui calls, key tables and title()
in tr(), so xgettext can extract them. Reviewed by hand afterwards; not part of the build.
usage: wrap_strings.py FILE..."""
import re, sys

FUNCS = ("Text|TextWrapped|TextUnformatted|TextDisabled|BulletText|Checkbox|Button|SmallButton|"
         "RadioButton|SliderFloat|SliderFloat2|SliderFloat3|SliderInt|SliderInt2|SliderAngle|"
         "InputInt|InputFloat|InputDouble|InputScalar|InputScalarN|InputText|InputTextWithHint|"
         "CollapsingHeader|TreeNode|TreeNodeEx|Combo|BeginCombo|Selectable|MenuItem|BeginMenu|"
         "LabelText|ColorEdit3|ColorEdit4|DragFloat|DragFloat3|DragInt|PlotLines|PlotHistogram|"
         "BeginTabItem|TableSetupColumn|SetTooltip|Begin|ProgressBar|ArrowButton|SeparatorText")
LIT = r'(?:"(?:[^"\\]|\\.)*"\s*)+'
call = re.compile(r'(ImGui::(?:' + FUNCS + r')\(\s*)(' + LIT + r')')
colored = re.compile(r'(ImGui::TextColored\(\s*[^,]+,\s*)(' + LIT + r')')

def worth(lit):
    body = ''.join(re.findall(r'"((?:[^"\\]|\\.)*)"', lit))
    shown = body.split('##')[0]
    shown = re.sub(r'%[-+ #0-9.$]*[lhzjtL]*[a-zA-Z%]', '', shown)
    return len(re.findall(r'[A-Za-z]{2,}', shown)) > 0

def wrap(m):
    lit = m.group(2).rstrip()
    tail = m.group(2)[len(lit):]
    if not worth(lit):
        return m.group(0)
    return m.group(1) + 'tr(' + lit + ')' + tail

for path in sys.argv[1:]:
    src = open(path).read()
    out = call.sub(wrap, src)
    out = colored.sub(wrap, out)
    # title() { return "..."; }
    out = re.sub(r'(title\(\) const override \{\s*return )(' + LIT + r')(;)',
                 lambda m: m.group(1) + 'tr(' + m.group(2).rstrip() + ')' + m.group(3), out)
    # KeyHelp / OptionHelp rows: {"key", "what"} and {"name", "ARG", "what"}
    def row(m):
        parts = m.group(1), m.group(2)
        key = m.group(1)
        keybody = key[1:-1]
        if re.search(r'[A-Za-z]{2,}', keybody) and not keybody.startswith('Ctrl'):
            key = 'tr(' + key + ')'
        return '{' + key + ', tr(' + m.group(2) + ')}'
    out = re.sub(r'\{("(?:[^"\\]|\\.)*"),\s*("(?:[^"\\]|\\.)*"\s*(?:"(?:[^"\\]|\\.)*"\s*)*)\}', row, out)
    if out != src:
        if '#include "core/i18n.h"' not in out:
            # after the first block of includes of the project
            idx = out.find('#include <')
            out = out[:idx] + '#include "core/i18n.h"\n\n' + out[idx:] if idx >= 0 else out
        open(path, 'w').write(out)
        print('wrapped', path)
