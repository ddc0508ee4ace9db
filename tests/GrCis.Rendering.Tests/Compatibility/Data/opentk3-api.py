# Lists OpenTK 3.3.3's public members of the math types GrCis uses, as TSV (type, kind, member).
# Run from this folder: python3 opentk3-api.py <git dir of github.com/opentk/opentk> > opentk3-api.tsv
import re, subprocess, sys
gitdir = sys.argv[1]
types = ["Vector2", "Vector3", "Vector4", "Vector2d", "Vector3d", "Vector4d", "Matrix3", "Matrix3d", "Matrix4", "Matrix4d",
         "Quaternion", "Quaterniond", "MathHelper"]

def source(t):
  text = subprocess.run(["git", "--git-dir", gitdir, "show", f"3.3.3:src/OpenTK/Math/{t}.cs"],
                        check=True, capture_output=True, text=True).stdout
  text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
  text = re.sub(r"^#if false$.*?^#endif$", "", text, flags=re.S | re.M)   # dead code is not API
  return "\n".join(re.sub(r"//.*", "", l) for l in text.splitlines())

def params(text):
  out, depth, cur = [], 0, ""
  for ch in text:
    if ch in "<([": depth += 1
    if ch in ">)]": depth -= 1
    if ch == "," and depth == 0: out.append(cur); cur = ""
    else: cur += ch
  if cur.strip(): out.append(cur)
  res = []
  for p in out:
    p = re.sub(r"\[[A-Za-z][^\]]*\]\s*", "", p.strip())   # parameter attributes
    p = p.split("=")[0].strip()
    words = p.split()
    res.append(" ".join(words[:-1]))                         # drop the parameter name
  return ", ".join(res)

def members(t, text):
  # Members are declared at one indentation level inside the struct/class (8 spaces).
  lines = text.splitlines()
  i = 0
  while i < len(lines):
    l = lines[i]
    m = re.match(r"^        public\s+(.*)", l)
    i += 1
    if not m: continue
    decl = m.group(1)
    # Join continuation lines until the declaration's header ends.
    while decl.count("(") > decl.count(")") or (("(" not in decl) and not re.search(r"[;{=]", decl) and i < len(lines) and lines[i].strip() != "{"):
      decl += " " + lines[i].strip(); i += 1
    decl = re.sub(r"\s+", " ", decl).strip()
    mods = re.match(r"((?:static |readonly |override |unsafe |const |new |extern )*)", decl).group(1).split()
    static = "static" in mods or "const" in mods
    d = re.sub(r"^(static |readonly |override |unsafe |const |new |extern )+", "", decl)
    mod = "static " if static else ""
    if d.startswith("struct ") or d.startswith("class "): continue
    if re.match(r"(implicit|explicit) operator", d):
      mm = re.match(r"(implicit|explicit) operator (\S+?)\s*\((.*?)\)", d)
      yield ("conversion", f"{mm.group(1)} {mm.group(2)}({params(mm.group(3))})"); continue
    mm = re.match(r"(\S+) operator (\S+?)\s*\((.*?)\)", d)
    if mm: yield ("operator", f"{mm.group(2)}({params(mm.group(3))})"); continue
    mm = re.match(rf"{t}\s*\((.*?)\)", d)
    if mm: yield ("ctor", f"{t}({params(mm.group(1))})"); continue
    mm = re.match(r"\S+ this\s*\[(.*?)\]", d)
    if mm: yield ("indexer", f"this[{params(mm.group(1))}]"); continue
    mm = re.match(r"(\S+(?:<[^>]*>)?) (\w+)\s*\((.*?)\)", d)
    if mm: yield (mod + "method", f"{mm.group(2)}({params(mm.group(3))})"); continue
    mm = re.match(r"(\S+) (\w+)\s*[;=]", d)
    if mm: yield (mod + ("const" if "const" in mods else "field"), mm.group(2)); continue
    mm = re.match(r"(\S+) (\w+)\s*(\{|$)", d)
    if mm: yield (mod + "property", mm.group(2)); continue
    mm = re.match(r"(\S+) (\w+)\s*,", d)   # public float X, Y;
    if mm:
      for n in re.findall(r"(\w+)\s*[,;]", d): yield (mod + "field", n)
      continue
    raise SystemExit(f"{t}: cannot read '{decl}'")

print("# OpenTK 3.3.3's public API of the math types GrCis uses: type, kind, member (parameter types with ref/out).")
print("# Generated once by Data/opentk3-api.py from the tag 3.3.3 of github.com/opentk/opentk (names and signatures only).")
for t in types:
  seen = set()
  for kind, member in members(t, source(t)):
    key = (kind, member)
    if key in seen: continue
    seen.add(key)
    print(f"{t}\t{kind}\t{member}")
