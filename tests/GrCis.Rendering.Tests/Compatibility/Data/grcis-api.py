# Lists the public types and the public or protected members of GrCis's common/ library at the last commit of
# each course year, as TSV: years, file, kind, type, member (the member with its parameter types and ref/out/in).
# Course year Y runs from September Y to August Y+1; its list is read at the last commit of master (first
# parent) before 1 September Y+1. The newest year, still running when the repository stopped, uses the newest commit.
# Run from this folder (Python 3, standard library only):
#   python3 grcis-api.py <git dir of github.com/pepcape/grcis> > grcis-api-years.tsv
# or, for the library of one commit in the format of grcis-common-api.tsv:
#   python3 grcis-api.py <git dir> <commit>
# --signatures adds a column with each declaration's modifiers (static, virtual, ...) and (return) type, to see
# what changed between years beyond names and parameters (not used by the tests).
# The C# is read by a small scanner, enough for what common/ contains: #if blocks are dropped (no symbol is
# defined: LOGGING, DEBUG, TRIANGLE_NORMALS_BEZIER and false only guard logging or experiments), #else kept.
import re, subprocess, sys

FIRST_YEAR = 2015


def git(gitdir, *args):
  out = subprocess.run(["git", "--git-dir", gitdir, *args], check=True, capture_output=True).stdout
  try:
    return out.decode("utf-8-sig")
  except UnicodeDecodeError:
    return out.decode("cp1250")   # some older sources are in the Czech Windows code page


def year_commits(gitdir):
  """(year, commit hash, commit date) for each course year from FIRST_YEAR to the newest commit's."""
  newest = git(gitdir, "log", "-1", "--first-parent", "--format=%H %cs", "master").split()
  rows = []
  year = FIRST_YEAR
  while True:
    cut = f"{year + 1}-09-01T00:00:00"
    if cut > newest[1]:
      rows.append((year, newest[0], newest[1]))
      return rows
    h, d = git(gitdir, "log", "-1", "--first-parent", f"--before={cut}", "--format=%H %cs", "master").split()
    rows.append((year, h, d))
    year += 1


def preprocess(text):
  """Drops #if blocks (all symbols undefined), keeps #else branches, removes other directives."""
  out, stack = [], []   # stack: whether the current branch is active
  for line in text.splitlines():
    s = line.strip()
    if s.startswith("#if"):
      stack.append([False, False])   # [active, some branch taken]
    elif s.startswith("#elif"):
      stack[-1][0] = False
    elif s.startswith("#else"):
      stack[-1][0] = not stack[-1][1] and not stack[-1][0]
      stack[-1][1] = True
    elif s.startswith("#endif"):
      stack.pop()
    elif s.startswith("#"):
      continue
    elif all(b[0] for b in stack):
      out.append(line)
      continue
    out.append("")
  return "\n".join(out)


def strip(text):
  """Comments removed, string and character literals emptied (their braces and quotes would mislead the scanner)."""
  out, i, n = [], 0, len(text)
  while i < n:
    c = text[i]
    if text.startswith("//", i):
      j = text.find("\n", i)
      i = n if j < 0 else j
    elif text.startswith("/*", i):
      j = text.find("*/", i + 2)
      i = n if j < 0 else j + 2
      out.append(" ")
    elif c == '"' or (c in "@$" and i + 1 < n and text[i + 1] in '"@$'):
      # Prefixes $ and @ in any order, then the string.
      j = i
      verbatim = interp = False
      while text[j] in "@$":
        verbatim |= text[j] == "@"
        interp |= text[j] == "$"
        j += 1
      j += 1
      depth = 0
      while j < n:
        if interp and text[j] == "{":
          if text.startswith("{{", j) and depth == 0: j += 2; continue
          depth += 1
        elif interp and text[j] == "}" and depth > 0:
          depth -= 1
        elif depth == 0 and verbatim and text.startswith('""', j):
          j += 2; continue
        elif depth == 0 and not verbatim and text[j] == "\\":
          j += 2; continue
        elif text[j] == '"' and depth == 0:
          break
        elif text[j] == '"' and depth > 0:
          # a plain string inside an interpolation hole
          j += 1
          while j < n and text[j] != '"':
            j += 2 if text[j] == "\\" else 1
        j += 1
      out.append('""')
      i = j + 1
    elif c == "'":
      j = i + 1
      while j < n and text[j] != "'":
        j += 2 if text[j] == "\\" else 1
      out.append("' '")
      i = j + 1
    else:
      out.append(c)
      i += 1
  return "".join(out)


def skip_block(text, i):
  """Index after the brace block opening at text[i] == '{'."""
  depth = 0
  while i < len(text):
    if text[i] == "{": depth += 1
    elif text[i] == "}":
      depth -= 1
      if depth == 0: return i + 1
    i += 1
  raise ValueError("unbalanced braces")


def skip_to_semicolon(text, i):
  """Index after the ';' ending an initializer or expression body (braces of lambdas and initializers nest)."""
  depth = 0
  while i < len(text):
    c = text[i]
    if c in "{([": depth += 1
    elif c in "})]": depth -= 1
    elif c == ";" and depth == 0: return i + 1
    i += 1
  raise ValueError("missing ';'")


def split_top(text, sep=","):
  parts, depth, cur = [], 0, ""
  for ch in text:
    if ch in "<([{": depth += 1
    if ch in ">)]}": depth -= 1
    if ch == sep and depth == 0:
      parts.append(cur); cur = ""
    else:
      cur += ch
  if cur.strip(): parts.append(cur)
  return parts


def balanced(text, i):
  """The text inside the parentheses opening at text[i]."""
  depth = 0
  for j in range(i, len(text)):
    if text[j] == "(": depth += 1
    elif text[j] == ")":
      depth -= 1
      if depth == 0: return text[i + 1:j]
  raise ValueError(f"unbalanced parentheses in '{text}'")


def norm_type(t):
  t = re.sub(r"\s+", " ", t.strip())
  t = re.sub(r"\s*([<>\[\]?,])\s*", r"\1", t)
  return t.replace(",", ", ")


def params(text):
  res = []
  for p in split_top(text):
    p = re.sub(r"\[[A-Za-z][^\]]*\]\s*", "", p.strip())   # parameter attributes
    p = split_top(p, "=")[0].strip()                      # default value
    m = re.match(r"((?:(?:ref|out|in|params|this)\s+)*)(.*)\s+@?\w+$", p, re.S)
    mods = m.group(1).split()
    mods = [x for x in mods if x != "this"]
    res.append(" ".join(mods + [norm_type(m.group(2))]))
  return ", ".join(res)


TYPE_KW = re.compile(r"\b(class|struct|interface|enum|record)\s+(\w+)\s*(<[^{]*?>)?")
MODIFIERS = {"public", "protected", "private", "internal", "static", "readonly", "const", "virtual", "override",
             "abstract", "sealed", "new", "unsafe", "extern", "volatile", "partial", "async", "event", "implicit",
             "explicit", "fixed"}


def access(mods, in_interface):
  if "private" in mods and "protected" in mods: return None    # private protected
  if "public" in mods: return ""
  if "protected" in mods: return "protected "
  if in_interface and "private" not in mods and "internal" not in mods: return ""
  return None


def decl(mods, type_text):
  """The declaration's modifiers other than access, and its (return) type: what --signatures shows."""
  words = [w for w in mods if w not in ("public", "protected", "internal")] + ([norm_type(type_text)] if type_text.strip() else [])
  return " ".join(words)


def members(path, text):
  """Yields (kind, type, member, declaration) for the public API of one source file."""
  text = strip(preprocess(text))
  n = len(text)

  def scan(i, end, ns, outer, outer_name, visible, kind):
    """Scans declarations in text[i:end]; ns = namespace, outer = enclosing type's reflection name (or None)."""
    while i < end:
      # One declaration: read its header up to '{', ';' or '=' at depth 0.
      while i < end and text[i] in " \t\r\n;": i += 1
      if i >= end: return
      if kind == "enum":
        body = text[i:end]
        for item in split_top(body):
          name = split_top(item, "=")[0].strip()
          name = re.sub(r"\[[^\]]*\]\s*", "", name).strip()
          if name and visible: yield ("field", outer, name, "const")
        return
      start, depth = i, 0
      while i < end:
        c = text[i]
        if c in "([": depth += 1
        elif c in ")]": depth -= 1
        elif depth == 0 and (c in "{;" or (c == "=" and text[i + 1] not in "=" and text[i - 1] not in "=!<>")):
          break
        i += 1
      header = re.sub(r"\s+", " ", text[start:i]).strip()
      header = re.sub(r"^(\[[^\]]*(?:\[[^\]]*\][^\]]*)*\]\s*)+", "", header).strip()   # attributes
      stop = text[i] if i < end else ";"
      arrow = stop == "=" and text[i + 1] == ">"
      tm = TYPE_KW.search(header)
      if header.startswith("namespace ") or header == "namespace":
        inner_end = skip_block(text, i) - 1
        yield from scan(i + 1, inner_end, header.split()[1], None, None, True, None)
        i = inner_end + 1
        continue
      if header.startswith("using ") or header.startswith("extern alias"):
        i = skip_to_semicolon(text, i) if stop != ";" else i + 1
        continue
      words = header.split()
      mods = []
      for w in words:
        if w in MODIFIERS: mods.append(w)
        else: break
      rest = " ".join(words[len(mods):])
      acc = access(mods, kind == "interface")
      if outer is None and acc is None and ("internal" not in mods and "private" not in mods):
        acc = None   # top-level types without a modifier are internal
      if tm and tm.start() == header.find(tm.group(0)) and "(" not in header[:tm.start()] and stop == "{" \
         and re.match(r"^(\w+ )*(class|struct|interface|enum|record) ", header):
        name = tm.group(2)
        arity = len(split_top(tm.group(3)[1:-1])) if tm.group(3) else 0
        full = name + (f"`{arity}" if arity else "")
        full = (f"{outer}+{full}" if outer else (f"{ns}.{full}" if ns else full))
        vis = visible and acc == ""   # protected nested types (helpers of one class) are left out
        if vis: yield ("type", full, tm.group(1), " ".join(mods))
        inner_end = skip_block(text, i) - 1
        yield from scan(i + 1, inner_end, ns, full, name, vis, tm.group(1))
        i = inner_end + 1
        continue
      # A member (or a delegate type).
      if stop == "{":
        i = skip_block(text, i)
        # A property initializer after the accessor block.
        j = i
        while j < end and text[j] in " \t\r\n": j += 1
        if j < end and text[j] == "=" and text[j + 1] != ">" and "(" not in rest.split("{")[0]:
          i = skip_to_semicolon(text, j)
      elif stop == "=":
        i = skip_to_semicolon(text, i)
      else:
        i += 1
      if outer is None and not rest.startswith("delegate ") or not visible or acc is None:
        continue
      yield from member(rest, acc, mods, stop, arrow, ns, outer, outer_name, visible)

  def member(rest, acc, mods, stop, arrow, ns, outer, outer_name, visible):
    if rest.startswith("delegate "):
      if acc != "": return   # like nested types, a protected delegate type is left out
      m = re.match(r"delegate .*?(\w+)\s*(<[^>]*>)?\s*\(", rest)
      arity = len(split_top(m.group(2)[1:-1])) if m.group(2) else 0
      name = m.group(1) + (f"`{arity}" if arity else "")
      full = f"{outer}+{name}" if outer else (f"{ns}.{name}" if ns else name)
      yield ("type", full, "delegate", decl(mods, rest[len("delegate "):].split(m.group(1))[0]))
      return
    if rest.startswith("~"): return
    m = re.match(r"(?:(?:implicit|explicit) )?operator (\S+?)\s*\((.*)\)$", rest) or \
        re.match(r".* operator\s*(\S+?)\s*\((.*)\)$", rest)
    if m and "operator" in rest.split("(")[0]:
      if "implicit" in mods or "explicit" in mods:
        conv = "implicit" if "implicit" in mods else "explicit"
        yield ("conversion", outer, f"{acc}{conv} {m.group(1)}({params(m.group(2))})", decl(mods, ""))
      else:
        yield ("operator", outer, f"{acc}{m.group(1)}({params(m.group(2))})", decl(mods, rest.split(" operator")[0]))
      return
    m = re.match(rf"{re.escape(outer_name)}\s*\(", rest)
    if m:
      yield ("ctor", outer, f"{acc}.ctor({params(balanced(rest, m.end() - 1))})", decl(mods, ""))
      return
    m = re.match(r".*?\bthis\s*\[(.*)\]$", rest)
    if m and stop != ";":
      yield ("property", outer, f"{acc}Item", decl(mods, rest.split("this")[0]))
      return
    m = re.match(r"(.+?)\s+(?:[\w.]+\.)?(\w+)\s*(<[^()]*>)?\s*\((.*)\)(\s*where .*)?$", rest)
    if m and "event" not in mods:
      yield ("method", outer, f"{acc}{m.group(2)}({params(m.group(4))})", decl(mods, m.group(1)))
      return
    kind = "event" if "event" in mods else ("property" if stop == "{" or arrow else "field")
    # Fields may declare several names: "public int a, b;"
    if kind == "field" or kind == "event":
      decls = split_top(rest)
      first = decls[0].split()
      names = [first[-1]] + [d.strip().split()[0] for d in decls[1:]]
    else:
      names = [rest.split()[-1]]
    for nm in names:
      if not re.match(r"^@?\w+$", nm): raise SystemExit(f"{path}: cannot read '{rest}'")
      yield (kind, outer, f"{acc}{nm}", decl(mods, " ".join(split_top(rest)[0].split()[:-1])))

  yield from scan(0, n, "", None, None, True, None)


def library(gitdir, commit, signatures=False):
  """Set of (file, kind, type, member) of common/ at commit; with signatures, each also has its declaration."""
  files = [f for f in git(gitdir, "ls-tree", "-r", "--name-only", commit, "common/").split("\n") if f.endswith(".cs")]
  rows = set()
  for f in files:
    src = git(gitdir, "show", f"{commit}:{f}")
    name = f[len("common/"):]
    for kind, t, mem, d in members(f, src):
      rows.add((name, kind, t, mem, d) if signatures else (name, kind, t, mem))
  return rows


def year_ranges(years, all_years):
  """'2016-2018,2021' for the years a line is in."""
  idx = sorted(all_years.index(y) for y in years)
  out, k = [], 0
  while k < len(idx):
    j = k
    while j + 1 < len(idx) and idx[j + 1] == idx[j] + 1: j += 1
    a, b = all_years[idx[k]], all_years[idx[j]]
    out.append(str(a) if a == b else f"{a}-{b}")
    k = j + 1
  return ",".join(out)


def main():
  args = [a for a in sys.argv[1:] if not a.startswith("--")]
  signatures = "--signatures" in sys.argv
  gitdir = args[0]
  if len(args) > 1:
    h, d = git(gitdir, "log", "-1", "--format=%h %cs", args[1]).split()
    print(f"# GrCis common/ at {h} ({d}): file, kind, type, member. Generated by: python3 grcis-api.py <git dir of github.com/pepcape/grcis> {h}")
    for r in sorted(library(gitdir, args[1], signatures)):
      print("\t".join(r))
    return
  years = year_commits(gitdir)
  where = {}
  for y, h, d in years:
    for r in library(gitdir, h, signatures):
      where.setdefault(r, []).append(y)
  all_years = [y for y, _, _ in years]
  print("# GrCis common/ public types and public/protected members per course year (September Y to August Y+1),")
  print("# read at the last master commit of the year; generated by grcis-api.py (names and signatures only).")
  print("# years\tfile\tkind\ttype\tmember" + ("\tdeclaration" if signatures else ""))
  for y, h, d in years:
    print(f"#commit\t{y}\t{d}\t{h[:7]}")
  for r in sorted(where, key=lambda r: (r[0], r[1], r[2], r[3], where[r])):
    print(year_ranges(where[r], all_years) + "\t" + "\t".join(r))


if __name__ == "__main__":
  main()
