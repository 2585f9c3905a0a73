"""Puts code at the start of lab functions, to make broken or hostile submissions.

    python3 instructor/scripts/lib/inject.py FOLDER LAB FUNCTION CODE [LAB FUNCTION CODE ...]

FOLDER holds the lab files (NN_name.cpp); CODE becomes the first line of the
body of FUNCTION in LAB.cpp. '#include <...>' directives at the start of CODE
go to the top of the file instead.
"""
import re
import sys

folder, triples = sys.argv[1], sys.argv[2:]
if len(triples) % 3:
    sys.exit("inject.py: expected LAB FUNCTION CODE triples")
for lab, function, code in zip(triples[0::3], triples[1::3], triples[2::3]):
    path = f"{folder}/{lab}.cpp"
    text = open(path).read()
    leading = re.match(r"(\s*#include\s*<[^>]+>)*", code).group(0)
    includes = re.findall(r"#include\s*<[^>]+>", leading)
    body = code[len(leading):].strip()
    text, count = re.subn(r"(\n[^\n]*\b" + function + r"\([^)]*\) \{\n)", lambda m: m.group(1) + "    " + body + "\n", text, count=1)
    if count != 1:
        sys.exit(f"inject.py: no function {function} in {path}")
    open(path, "w").write("\n".join(includes) + ("\n" if includes else "") + text)
