# The sites where scripts/mutants --sample plants a bug: a C++ token-level generator of one-edit mutants.
"""Finds mutation sites in C++ source text, token by token.

A site is one edit of one line: an operator swapped (+ -, * /, < <=, == !=,
&& ||), a constant changed (+1, -1, x2), two arguments of a call swapped, a
statement dropped, an if's condition negated, a unary minus removed, true and
false exchanged. Comments, string and character literals and preprocessor
lines are skipped; a binary operator counts only with spaces on both sides
(the project's format), so template brackets and pointer or reference
types (T* p, auto&& x) are never mutated.

Each site has a stable id, FILE:HASH:OPERATOR:N, from the file, a hash of the
line's text (stripped), the operator and its index among that operator's
sites on lines of the same text in the file: it survives edits elsewhere in the file, so a triaged
equivalent mutant is remembered across runs.
"""
import hashlib
import re
from dataclasses import dataclass

# Tokens, longest first; anything else is one character of punctuation.
TOKEN = re.compile(r"""
    (?P<space>\s+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<raw>R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)")
  | (?P<string>"(?:\\.|[^"\\\n])*")
  | (?P<char>'(?:\\.|[^'\\\n])+')
  | (?P<number>0[xXbB][0-9a-fA-F']+[uUlL]*|(?:\d[\d']*\.?[\d']*|\.\d+)(?:[eE][+-]?\d+)?[uUlLfF]*)
  | (?P<word>[A-Za-z_]\w*)
  | (?P<op><<=|>>=|->|::|\+\+|--|\+=|-=|\*=|/=|==|!=|<=|>=|&&|\|\||<<|>>|.)
""", re.S | re.X)


@dataclass
class Token:
    kind: str
    text: str
    start: int  # offset in the file


@dataclass
class Site:
    file: str
    line: int  # 1-based
    operator: str
    start: int  # offset of the replaced text in the file
    old: str
    new: str
    id: str = ""

    def apply(self, text):
        assert text[self.start:self.start + len(self.old)] == self.old, "the site's text moved"
        return text[:self.start] + self.new + text[self.start + len(self.old):]


def tokens(text):
    """The code tokens of a C++ file: no spaces, comments or preprocessor lines."""
    out, at_line_start, in_directive = [], True, False
    for m in TOKEN.finditer(text):
        kind = "string" if m.lastgroup == "raw" else m.lastgroup
        if kind == "space":
            if "\n" in m.group() and not text[m.start() - 1:m.start()] == "\\":
                at_line_start, in_directive = True, False
            continue
        if kind == "comment":
            continue
        if at_line_start and m.group() == "#":
            in_directive = True
        at_line_start = False
        if not in_directive:
            out.append(Token(kind, m.group(), m.start()))
    return out


# Policy as tables: each operator's replacement.
SWAPPED = {"+": "-", "-": "+", "*": "/", "/": "*", "<": "<=", "<=": "<", ">": ">=", ">=": ">",
           "==": "!=", "!=": "==", "&&": "||", "||": "&&", "+=": "-=", "-=": "+=", "*=": "/=", "/=": "*="}
NOT_OPERANDS = {"return", "case", "throw", "else", "do", "co_return", "new", "delete", "sizeof"}
STATEMENT_STARTERS = {"=", "+=", "-=", "*=", "/=", "++", "--", "(", ".", "->", "["}
TYPE_WORDS = {"return", "if", "for", "while", "switch", "case", "break", "continue", "goto", "throw", "using",
              "typedef", "static_assert", "co_return", "delete", "default", "else", "do", "try"}


def is_operand_end(tok):
    return (tok.kind in ("number", "string", "char") or (tok.kind == "word" and tok.text not in NOT_OPERANDS)
            or tok.text in (")", "]"))


def spaced(text, tok):
    end = tok.start + len(tok.text)
    return text[tok.start - 1:tok.start] == " " and text[end:end + 1] == " "


def changed_constants(literal):
    """The literal +1, -1 and x2, as C++ text (one of them may equal another)."""
    body = literal.rstrip("uUlLfF")
    suffix = literal[len(body):]
    body = body.replace("'", "")  # digit separators (3'600'000)
    try:
        value = int(body) if re.fullmatch(r"\d+", body) else float(body)
    except ValueError:
        return []
    if isinstance(value, int):
        forms = [value + 1, value - 1 if value > 0 else None, value * 2 if value != 0 else None]
        return [f"{v}{suffix}" for v in forms if v is not None and v >= 0]
    forms = [value + 1, value - 1, value * 2 if value != 0 else None]
    return [f"{v!r}{suffix}" for v in forms if v is not None]


def operator_sites(text, toks):
    for i, tok in enumerate(toks):
        # Binary operators stand between spaces in the project's format; a
        # pointer or reference type (T* p, auto&& x) and template brackets do not.
        if tok.kind == "op" and tok.text in SWAPPED and i > 0 and is_operand_end(toks[i - 1]) and spaced(text, tok):
            yield "operator", tok.start, tok.text, SWAPPED[tok.text]


def constant_sites(toks):
    for i, tok in enumerate(toks):
        if tok.kind != "number" or (i > 0 and toks[i - 1].text in ("[", "<")):
            continue  # an array's size or a template argument: rarely compiles changed
        for new in changed_constants(tok.text):
            if new != tok.text:
                yield "constant", tok.start, tok.text, new


def sign_and_bool_sites(toks):
    for i, tok in enumerate(toks[:-1]):
        if tok.text in ("true", "false"):
            yield "boolean", tok.start, tok.text, "false" if tok.text == "true" else "true"
        elif tok.text == "-" and i > 0 and not is_operand_end(toks[i - 1]) and \
                (toks[i + 1].kind in ("word", "number") or toks[i + 1].text == "("):
            yield "sign", tok.start, "-", ""


def matching(toks, i, open_text, close_text):
    """Index of the token closing the bracket at i, or None."""
    depth = 0
    for j in range(i, len(toks)):
        depth += (toks[j].text == open_text) - (toks[j].text == close_text)
        if depth == 0:
            return j
    return None


def argument_swap_sites(text, toks):
    """f(a, b) -> f(b, a), for calls of exactly two arguments on one line."""
    for i, tok in enumerate(toks[:-1]):
        if tok.kind != "word" or toks[i + 1].text != "(" or tok.text in TYPE_WORDS:
            continue
        close = matching(toks, i + 1, "(", ")")
        if close is None:
            continue
        depth, commas = 0, []
        for j in range(i + 2, close):
            depth += toks[j].text in "([{" and toks[j].kind == "op"
            depth -= toks[j].text in ")]}" and toks[j].kind == "op"
            if depth == 0 and toks[j].text == ",":
                commas.append(j)
        if len(commas) != 1 or commas[0] == i + 2 or commas[0] + 1 == close:
            continue
        a0, a1 = toks[i + 2].start, toks[commas[0] - 1].start + len(toks[commas[0] - 1].text)
        b0, b1 = toks[commas[0] + 1].start, toks[close - 1].start + len(toks[close - 1].text)
        first, second = text[a0:a1], text[b0:b1]
        if first == second or "\n" in text[a0:b1]:
            continue
        yield "swap-arguments", a0, text[a0:b1], second + text[a1:b0] + first


def statement_sites(text, toks):
    """A dropped expression statement, and an if's condition negated."""
    for i, tok in enumerate(toks[:-1]):
        after_boundary = i > 0 and toks[i - 1].text in (";", "{", "}")
        if tok.text == "if" and toks[i + 1].text == "(":
            close = matching(toks, i + 1, "(", ")")
            if close is not None:
                a, b = toks[i + 1].start, toks[close].start + 1
                yield "negate-condition", a, text[a:b], "(!" + text[a:b] + ")"
        if not after_boundary or tok.kind != "word" or tok.text in TYPE_WORDS:
            continue
        if toks[i + 1].text not in STATEMENT_STARTERS:
            continue
        end = next((j for j in range(i, min(len(toks), i + 200)) if toks[j].text in (";", "{", "}")), None)
        if end is None or toks[end].text != ";":
            continue
        a, b = tok.start, toks[end].start + 1
        if "\n" not in text[a:b] and toks[i - 1].text != ")":  # not the body of a for( ; ; )
            yield "drop-statement", a, text[a:b], ";"


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def sites(path, text):
    """Every site of one file, each with its stable id."""
    toks = tokens(text)
    found = [*operator_sites(text, toks), *constant_sites(toks), *sign_and_bool_sites(toks),
             *argument_swap_sites(text, toks), *statement_sites(text, toks)]
    lines = text.split("\n")
    out, seen = [], {}
    for operator, start, old, new in sorted(found, key=lambda s: (s[1], s[0], s[3])):
        line = line_of(text, start)
        digest = hashlib.sha1(lines[line - 1].strip().encode()).hexdigest()[:10]
        kind = f"{operator}:{old if operator in ('operator', 'constant', 'boolean', 'sign') else ''}->" \
               f"{new if operator in ('operator', 'constant', 'boolean') else ''}"
        key = (digest, kind)  # identical lines of a file are told apart by n
        n = seen[key] = seen.get(key, -1) + 1
        out.append(Site(path, line, operator, start, old, new, f"{path}:{digest}:{kind}:{n}"))
    return out
