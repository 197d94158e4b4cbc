#!/usr/bin/env python3
"""Names that test files of one program define at file scope, and their clashes.

The test files of a folder (unit/, integration/, interop/, gui/) are linked into one program
(tests/CMakeLists.txt). Two files that define the same class or function outside an anonymous
namespace break the one-definition rule: for a function the linker says so, but two classes of
one name with inline members are merged silently and one file runs the other's code. This
script lists, per folder, every class, struct, enum, function and variable defined at file
scope (global or a named namespace, not an anonymous one) by more than one file, and exits 1
when there is any. Usage: file_scope_names.py TESTS-DIR [FOLDER...]
"""
import os
import re
import sys
from collections import defaultdict

KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "catch", "decltype",
            "alignof", "static_assert", "Q_DECLARE_METATYPE", "Q_OBJECT", "QTEST_MAIN",
            "QTEST_GUILESS_MAIN", "QTEST_APPLESS_MAIN", "Q_LOGGING_CATEGORY", "Q_DECLARE_FLAGS"}


def strip(text):
    """Comments, string and character literals and preprocessor lines removed."""
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r'R"(\w*)\(.*?\)\1"', '""', text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
    text = re.sub(r"'(\\.|[^'\\\n])*'", "''", text)
    return re.sub(r"^[ \t]*#[^\n]*(\\\n[^\n]*)*", "", text, flags=re.M)


def file_scope_names(path):
    """(name, kind) defined at file scope outside anonymous namespaces."""
    text = strip(open(path, encoding="utf-8").read())
    names = set()
    # stack of scopes: "anon", "ns" (named namespace), "block" (anything else)
    stack = []
    statement = ""
    i = 0
    while i < len(text):
        c = text[i]
        if c == "{":
            head = statement.strip()
            at_file_scope = all(s == "ns" for s in stack)
            m_ns = re.search(r"(?:^|\s)namespace\s*([\w:]*)\s*$", head)
            if m_ns is not None and re.match(r"^(inline\s+)?namespace\b", head.split(";")[-1].strip()):
                stack.append("ns" if m_ns.group(1) else "anon")
            else:
                if at_file_scope:
                    m = re.search(r"\b(class|struct|union|enum(?:\s+class)?)\s+(\w+)\s*(?:final\s*)?(?::[^{]*)?$", head)
                    if m:
                        names.add((m.group(2), m.group(1).split()[0]))
                    else:
                        m = re.search(r"(?:^|[\s*&>])([A-Za-z_]\w*)\s*\([^;]*\)\s*(?:const\s*)?(?:noexcept\s*)?(?:->[^{]*)?$", head)
                        if m and m.group(1) not in KEYWORDS and "::" not in head.split("(")[0][-len(m.group(1)) - 2:]:
                            if not re.match(r"^(static\b|.*\bstatic\s)", head):
                                names.add((m.group(1), "function"))
                stack.append("block")
            statement = ""
        elif c == "}":
            if stack:
                stack.pop()
            statement = ""
        elif c == ";":
            head = statement.strip()
            if all(s == "ns" for s in stack) and head and not head.startswith(("using", "typedef", "extern", "template", "static ", "friend", "namespace")):
                # a variable defined at file scope: "Type name = ...;" or "Type name;"
                m = re.match(r"^(?:const\s+|constexpr\s+|inline\s+)*[\w:<>,\s*&]+?\s+\**(\w+)\s*(?:=|\[|\{|$)", head)
                if m and "(" not in head.split("=")[0] and m.group(1) not in KEYWORDS:
                    if not re.match(r"^(const|constexpr)\b", head):  # const: internal linkage
                        names.add((m.group(1), "variable"))
            statement = ""
        else:
            statement += c
        i += 1
    return names


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    root = sys.argv[1]
    folders = sys.argv[2:] or ["unit", "integration", "interop", "gui"]
    clashes = 0
    for folder in folders:
        where = defaultdict(list)
        directory = os.path.join(root, folder)
        for name in sorted(os.listdir(directory)):
            if name.startswith("tst_") and name.endswith(".cpp"):
                for entry in file_scope_names(os.path.join(directory, name)):
                    where[entry].append(name)
        for (name, kind), files in sorted(where.items()):
            if len(files) > 1:
                clashes += 1
                print(f"{folder}: {kind} {name} defined at file scope in {', '.join(files)}")
    if clashes:
        print(f"{clashes} name(s) defined at file scope by more than one test file of a program: "
              "put the helpers in an anonymous namespace (namespace { ... })")
        return 1
    print("no test file of a program defines a file-scope name another one defines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
