"""Plain-text formulas of the harness (error definitions, axis labels, summaries: "sum_i (m_i/rho_i)
|rho_i - rho_exact(x_i, t)|") as LaTeX: the formula spans set as math ($\\sum_i (m_i/\\rho_i) |...|$),
the prose around them escaped. The same math serves pdflatex and matplotlib's mathtext (Computer
Modern), so a figure's labels read like its caption.

The harness writes formulas in a small ASCII notation: identifiers with subscripts after "_"
(v_phi,i is v_{phi,i}), Greek letters by name, sqrt(...), "^" for powers and <=, >= for
inequalities. A token is mathematical when it is such an identifier, a Greek letter, a single
letter, a function applied to a bracket, an operator, or a number next to one of these; runs of
mathematical tokens (with the spaces and the brackets between them) form one span."""
import re
import unicodedata

GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "eps", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu", "nu",
         "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi",
         "Sigma", "Phi", "Psi", "Omega"}
FUNCS = {"sqrt": r"\sqrt", "exp": r"\exp", "ln": r"\ln", "log": r"\log", "sin": r"\sin", "cos": r"\cos", "tan": r"\tan",
         "max": r"\max", "min": r"\min", "sum": r"\sum", "prod": r"\prod", "mean": r"\mathrm{mean}", "vol": r"\mathrm{vol}",
         "erf": r"\mathrm{erf}", "sign": r"\mathrm{sign}", "abs": r"\mathrm{abs}"}
OPS = {"<=": r"\le ", ">=": r"\ge ", "!=": r"\ne ", "==": "=", "*": r"\,", "~": r"\sim ", "+-": r"\pm ", "%": r"\%", "->": r"\to "}
# One token: a dimension ("2D"), an identifier with its subscripts (v_phi,i; rho_exact), a number,
# a two-character operator, one character.
TOKEN = re.compile(r"(?P<dim>\d[Dd]\b)|(?P<id>[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+(?:,[A-Za-z0-9](?![A-Za-z0-9]))?)*)"
                   r"|(?P<num>\d+(?:\.\d+)?(?:e[-+]?\d+)?)|(?P<op><=|>=|!=|==|\+-|->)|(?P<sp>\s+)|(?P<ch>.)", re.S)
MATH_CH = set("=<>+-*/^|()[]~")
SPECIALS = {"\\": r"\textbackslash{}", "^": r"\^{}", "~": r"$\sim$", "<": r"$<$", ">": r"$>$", "|": r"$|$"}
UNICODE_MATH = {"±": r"\pm", "×": r"\times", "≤": r"\le", "≥": r"\ge", "−": "-", "≈": r"\approx", "∞": r"\infty",
                "²": "^2", "³": "^3", "·": r"\cdot", "∫": r"\int", "∑": r"\sum", "√": r"\surd", "∇": r"\nabla", "∂": r"\partial"}


def prose(text):
    """Plain text to LaTeX text: specials escaped, Greek letters and common symbols as math,
    anything else outside ASCII spelled as its Unicode name (pdflatex would stop on it)."""
    out = []
    for ch in str(text):
        if ch == "_":  # identifiers (drift_baseline_present) may break after an underscore
            out.append(r"\_\allowbreak{}")
        elif ch in "\\{}%&#$^~<>|":
            out.append(SPECIALS.get(ch, "\\" + ch))
        elif ch in ",=":  # settings (euler=26,integrator=chapter) may break after a comma or an equals sign
            out.append(ch + r"\allowbreak{}")
        elif ord(ch) < 128:
            out.append(ch)
        elif ch in UNICODE_MATH:
            out.append(f"${UNICODE_MATH[ch]}$")
        elif ch in "–—":
            out.append("--" if ch == "–" else "---")
        else:
            name = unicodedata.name(ch, "")
            m = re.match(r"GREEK (SMALL|CAPITAL) LETTER (\w+)$", name)
            if m:
                letter = m.group(2).lower()
                out.append(f"$\\{letter.capitalize() if m.group(1) == 'CAPITAL' else letter}$")
            else:
                out.append(f"[{name.lower() or '?'}]")
    return "".join(out)


def symbol(word):
    """One identifier part (no "_") as math: Greek letters, L1 as L_1, single letters as
    themselves, longer words upright."""
    if word in ("dt", "dx"):
        return "\\Delta " + word[1]
    if word in GREEK:
        return "\\epsilon" if word == "eps" else "\\" + word
    m = re.fullmatch(r"([A-Za-z])(\d+|inf)", word)
    if m:
        return m.group(1) + "_{" + (r"\infty" if m.group(2) == "inf" else m.group(2)) + "}"
    if word in FUNCS:
        return FUNCS[word]
    return word if len(word) == 1 or word.isdigit() else r"\mathrm{" + word + "}"


def identifier(name):
    """rho_exact as \\rho_{\\mathrm{exact}}, v_phi,i as v_{\\phi,i}, sum_i as \\sum_i, a norm's name
    L1_rho as L_1(\\rho)."""
    base, *subs = name.split("_")
    if subs and re.fullmatch(r"L(\d+|inf)", base):
        return symbol(base) + "(" + identifier("_".join(subs)) + ")"
    out = symbol(base)
    if subs and "_" in out:  # T0_x: a subscripted symbol takes a further subscript inside braces
        out = "{" + out + "}"
    for sub in subs:  # a second "_" nests one level deeper: c_v_x is c_{v_x}
        parts = [symbol(p) for p in sub.split(",")]
        out += "_{" + ",".join(parts)
    return out + "}" * len(subs)


def number(text):
    m = re.fullmatch(r"(\d+(?:\.\d+)?)e([-+]?\d+)", text)
    if m:
        return (f"{m.group(1)}\\times" if m.group(1) != "1" else "") + f"10^{{{int(m.group(2))}}}"
    return text


def tokens(text):
    out = []
    for m in TOKEN.finditer(str(text)):
        kind = m.lastgroup
        out.append([kind, m.group()])
    return out


def is_name(t):
    """An identifier that names something (spatial_gauss, amplitude_ratio) rather than a symbol
    with subscripts: a word for its base that is no Greek letter, function or norm, and words for
    all its subscripts."""
    base, *subs = t.split("_")
    norm = re.fullmatch(r"L(\d+|inf)", base)  # L1_p_contact: a norm of p_contact, as L1_rho is of rho
    if len(subs) > 1 and not norm and any(len(x) > 1 for x in [base] + subs):  # n24_L1_v, drift_baseline_present
        return True
    if base in FUNCS and any(len(x) > 1 and re.search(r"\d", x) for x in subs):  # sum_1d: a name, not a sum
        return True
    return (len(base) > 1 and base not in GREEK and base not in FUNCS and not re.fullmatch(r"L(\d+|inf)", base)
            and all(len(x) > 1 for x in subs))


def is_math_word(toks, k):
    kind, t = toks[k]
    nxt = toks[k + 1][1] if k + 1 < len(toks) else ""
    if kind != "id":
        return False
    if k > 0 and toks[k - 1][1] == "'":  # v_x's
        return False
    if "_" in t:
        return not is_name(t)
    if t in GREEK or t in ("dt", "dx") or re.fullmatch(r"[A-Za-z]\d+|[A-Z]inf", t):
        return True
    if t in FUNCS:
        return nxt == "("
    if len(t) == 1:
        return t != "a" and (t not in ("A", "I") or neighbour_math(toks, k))
    return False


def neighbour_math(toks, k):
    """Whether the nearest non-space token on either side is an operator or a mathematical word."""
    for step in (-1, 1):
        j = k + step
        while 0 <= j < len(toks) and toks[j][0] == "sp":
            j += step
        if 0 <= j < len(toks):
            kind, t = toks[j]
            if kind == "op" or (kind == "ch" and t in MATH_CH) or kind == "num" or (kind == "id" and (len(t) == 1 or "_" in t or t in GREEK)):
                return True
    return False


def classify(toks):
    """Marks each token math (True) or prose (False)."""
    m = [False] * len(toks)
    for k, (kind, t) in enumerate(toks):
        if kind == "id":
            m[k] = is_math_word(toks, k)
        elif kind == "op" or (kind == "num" and "e" in t):
            m[k] = True
    # Single-character operators and numbers: mathematical beside mathematical tokens; a hyphen
    # or slash joining two prose words without spaces (mass-weighted, and/or) stays prose.
    for _ in range(3):
        for k, (kind, t) in enumerate(toks):
            if m[k] or kind not in ("ch", "num"):
                continue
            if kind == "ch" and t not in MATH_CH:
                continue
            left = toks[k - 1] if k > 0 else ["sp", ""]
            right = toks[k + 1] if k + 1 < len(toks) else ["sp", ""]
            if kind == "ch" and t in "-/" and left[0] == "id" and right[0] == "id" and not (m[k - 1] and m[k + 1]):
                continue
            near = [j for j in (k - 1, k + 1, k - 2, k + 2) if 0 <= j < len(toks) and toks[j][0] != "sp"
                    and (abs(j - k) == 1 or toks[(j + k) // 2][0] == "sp")]
            if any(m[j] for j in near):
                m[k] = True
    for k, (kind, t) in enumerate(toks):  # a power's exponent is math whatever it is: (1 - dt)^steps
        if t == "^" and m[k] and k + 1 < len(toks) and toks[k + 1][0] in ("id", "num"):
            m[k + 1] = True
    balance(toks, m)
    return m


def balance(toks, m):
    """A bracket pair is math when both its brackets are and nothing prose lies between them;
    otherwise both brackets are prose (the math inside forms spans of its own). Unpaired math
    brackets become prose."""
    pairs, stack = {}, []
    for k, (kind, t) in enumerate(toks):
        if t in "([":
            stack.append(k)
        elif t in ")]" and stack:
            pairs[stack.pop()] = k
    for k in stack:
        m[k] = False
    closing = set(pairs.values())
    for k, (kind, t) in enumerate(toks):
        if t in ")]" and k not in closing:
            m[k] = False
    for o, c in sorted(pairs.items(), key=lambda p: p[1] - p[0]):
        inner = [j for j in range(o + 1, c) if toks[j][0] != "sp"]
        numbers = inner and all(toks[j][0] == "num" or toks[j][1] in ",-" for j in inner)  # an interval [-0.4, 0.4]
        is_math = numbers or ((m[o] or m[c] or any(m[j] for j in inner)) and all(m[j] or toks[j][1] == "," for j in inner))
        m[o] = m[c] = is_math
        if is_math:
            for j in inner:
                m[j] = True
    for k, (kind, t) in enumerate(toks):  # a function whose bracket holds prose is prose too: sqrt(sum_i |grad f|^2 ...)
        if kind == "id" and t in FUNCS and "_" not in t and k + 1 < len(toks) and toks[k + 1][1] == "(" and not m[k + 1]:
            m[k] = False
    return m


def render_math(toks):
    """A span of math tokens as LaTeX math (without the dollars): sqrt(...) as \\sqrt{...},
    x^(...) and x^2 as superscripts."""
    out = []
    k = 0
    while k < len(toks):
        kind, t = toks[k]
        if kind == "id" and t == "sqrt" and k + 1 < len(toks) and toks[k + 1][1] == "(":
            out.append(r"\sqrt{")
            k += 2
            depth = 1
            j = k
            while j < len(toks) and depth:
                depth += {"(": 1, ")": -1}.get(toks[j][1], 0)
                j += 1
            out.append(render_math(toks[k:j - 1]) + "}")
            k = j
            continue
        if kind == "ch" and t == "^" and k + 1 == len(toks):  # nothing left to raise
            out.append("^{}")
            k += 1
            continue
        if kind == "ch" and t == "^" and k + 1 < len(toks):
            if toks[k + 1][1] == "(":
                depth, j = 0, k + 1
                while j < len(toks):
                    depth += {"(": 1, ")": -1}.get(toks[j][1], 0)
                    j += 1
                    if not depth:
                        break
                out.append("^{" + render_math(toks[k + 2:j - 1]) + "}")
                k = j
                continue
            nxt = toks[k + 1]
            out.append("^{" + (identifier(nxt[1]) if nxt[0] == "id" else number(nxt[1]) if nxt[0] == "num" else nxt[1]) + "}")
            k += 2
            continue
        if kind == "id" and t == "sqrt":  # without its bracket
            out.append(r"\surd ")
        elif kind == "id":
            out.append(identifier(t) + " ")
        elif kind == "num":
            out.append(number(t))
        elif kind == "op" or t in OPS:
            out.append(OPS.get(t, t))
        elif kind == "sp":
            out.append(" ")
        elif kind == "dim":
            out.append(r"\mathrm{" + t + "}")
        else:
            out.append(t)
        k += 1
    return re.sub(r" +", " ", "".join(out)).strip()


def latex(text, for_tex=True):
    """Text with ASCII formulas as LaTeX: formula spans in $...$, the rest escaped for pdflatex
    (for_tex) or, for matplotlib's mathtext, left as it is but for its dollar signs."""
    toks = tokens(text)
    m = classify(toks)
    out, k = [], 0
    while k < len(toks):
        if not m[k]:
            # mathtext: Computer Modern's text font has no underscore (its slot holds a dot accent)
            out.append(prose(toks[k][1]) if for_tex else toks[k][1].replace("$", r"\$").replace("_", r"$\_$"))
            k += 1
            continue
        j = k
        while j < len(toks) and (m[j] or (toks[j][0] == "sp" and j + 1 < len(toks) and m[j + 1]) or
                                 (toks[j][1] == "," and any(m[i] and toks[i][1] in "([" for i in range(k, j)) and
                                  depth_at(toks, k, j) > 0)):
            j += 1
        span = render_math(toks[k:j])
        if for_tex and len(span) > 40:  # a long formula in running text may break after a slash
            span = span.replace("/", r"/\allowbreak{}")
        out.append("$" + span + "$")
        k = j
    return "".join(out)


def depth_at(toks, start, end):
    d = 0
    for kind, t in toks[start:end]:
        d += {"(": 1, "[": 1, ")": -1, "]": -1}.get(t, 0)
    return d


def mathtext(text):
    """A figure label: its formulas as mathtext, the rest as it is."""
    return latex(text, for_tex=False)


def error_name(name, for_tex=True):
    """An error's name: a norm of a quantity (L1_rho) or a Greek symbol with one subscript
    (rho_post) as math, any other name (shock_speed, sum_1d, rho_profile_L1) as it is written."""
    if re.fullmatch(r"L(\d+|inf)_[A-Za-z]+", name) or re.fullmatch(r"(%s)(_[A-Za-z0-9]+)?" % "|".join(GREEK), name):
        return "$" + identifier(name) + "$"
    return prose(name) if for_tex else name.replace("$", r"\$").replace("_", r"$\_$")
