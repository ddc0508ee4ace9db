#!/usr/bin/env python3
"""Builds OpenTK's own math test suites against GrCis.Mathematics' OpenTK.Mathematics types and runs them.

usage: opentk-suites.py <OpenTK git dir> <tag or commit> <GrCis.Mathematics.dll> <work dir>

The suites are read from the git dir at the given revision into <work dir> (never into the repository),
`open OpenTK` / C# namespace lookups are pointed at OpenTK.Mathematics, and every test (or generator) that
does not compile against our types is cut out, repeatedly, until the rest builds. Prints the counts:
tests in the suites, tests that compile, tests that pass.
"""
import os, re, subprocess, sys, xml.etree.ElementTree as ET

args = [a for a in sys.argv[1:] if not a.startswith('--')]
gitdir, rev, dll, work = args[:4]
# F# passes OpenTK 3's `ref x` arguments as ref cells, which bind a byref parameter but not an inref (C# `in`) one.
# GrCis declares those parameters `in` (OpenTK 4) and gives each such method a `ref` twin (files *.RefForms.cs), so the
# suites' own text compiles; --amp writes OpenTK 3's `ref x` as `&x` instead (to measure without the twins).
raw = '--amp' not in sys.argv
os.makedirs(work, exist_ok=True)

def git_show(path):
  return subprocess.run(['git', '-C', gitdir, 'show', f'{rev}:{path}'], check=True, capture_output=True).stdout.decode('utf-8-sig')

def git_ls(path):
  out = subprocess.run(['git', '-C', gitdir, 'ls-tree', '-r', '--name-only', rev, path], check=True, capture_output=True).stdout.decode()
  return [l for l in out.splitlines() if l]

def compile_order(fsproj):
  return re.findall(r'<Compile Include="([^"]+\.fs)"', git_show(fsproj))

PKGS = '''
    <PackageReference Include="FsCheck.Xunit" Version="2.16.5" />
    <PackageReference Include="Microsoft.NET.Test.Sdk" Version="17.12.0" />
    <PackageReference Include="xunit" Version="2.9.3" />
    <PackageReference Include="xunit.runner.visualstudio" Version="2.8.2" />'''

def project(kind, files, refs):
  items = ''.join(f'    <Compile Include="{f}" />\n' for f in files) if kind == 'fs' else ''
  prefs = ''.join(f'    <ProjectReference Include="{r}" />\n' for r in refs)
  return f'''<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <TargetFramework>net10.0</TargetFramework>
    <IsPackable>false</IsPackable>
    <TreatWarningsAsErrors>false</TreatWarningsAsErrors>
    <NoWarn>$(NoWarn);FS0064;FS3370;CS0618;CS8321;CS9191;CS9192</NoWarn>
    <Nullable>disable</Nullable>
    <RunAnalyzers>false</RunAnalyzers>
  </PropertyGroup>
  <ItemGroup>
{items}  </ItemGroup>
  <ItemGroup>{PKGS}
{prefs}    <Reference Include="GrCis.Mathematics"><HintPath>{os.path.abspath(dll)}</HintPath></Reference>
  </ItemGroup>
</Project>
'''

def fix(text, cs):
  if cs:
    return 'global using OpenTK.Mathematics;\n' + text if 'global using' not in text else text
  # xunit 2.9 builds EqualException with a factory (OpenTK 3's tests used xunit 2.3's constructor).
  text = re.sub(r'new Xunit\.Sdk\.EqualException\(', 'Xunit.Sdk.EqualException.ForMismatchedValues(', text)
  if not raw:
    text = re.sub(r'([(,]\s*)ref (\w+)', r'\1&\2', text)
  return re.sub(r'^open OpenTK\s*$', 'open OpenTK.Mathematics', text, flags=re.M)

START = re.compile(r'^(\s*)(\[<|let |static member |member |type |\[|public |private |internal )')
TESTATTR = re.compile(r'\[<(Property|Fact|Theory)|^\s*\[(Fact|Theory|Property)')

def indent(l):
  return len(l) - len(l.lstrip())

def cut(lines, ln, cs):
  """Blank the outermost member (test, generator, helper) around 0-based line ln; returns False if none."""
  if cs:
    # C#: the enclosing method, from its attributes to its closing brace at the same indent.
    i = ln
    while i >= 0 and (not re.match(r'^\s*(public|private|internal|static)\s[^=;]*\w\s*(\(.*)?$', lines[i]) or ' class ' in lines[i]):
      i -= 1
    if i < 0: return False
    ind = indent(lines[i])
    s = i
    while s > 0 and re.match(r'^\s*\[', lines[s - 1]) or (s > 0 and lines[s - 1].strip().startswith('///')):
      s -= 1
    e = i + 1
    while e < len(lines) and not (lines[e].strip() == '}' and indent(lines[e]) == ind):
      e += 1
    for k in range(s, min(e + 1, len(lines))): lines[k] = ''
    return True
  # F#: climb to a definition whose parent line (next less-indented line above) is a module/type/namespace header.
  i = ln
  cur = indent(lines[i]) if lines[i].strip() else 99
  while i >= 0:
    l = lines[i]
    if l.strip() and indent(l) <= cur:
      cur = indent(l)
      if START.match(l) and not l.strip().startswith('[<'):
        # parent
        p = i - 1
        while p >= 0 and (not lines[p].strip() or indent(lines[p]) >= indent(l)):
          p -= 1
        if p < 0 or re.match(r'^\s*(module|type|namespace|\[<)', lines[p]) or lines[p].rstrip().endswith('='):
          if p < 0 or re.match(r'^\s*(module|namespace)', lines[p]) or re.match(r'^\s*type .*=\s*$', lines[p]) or re.match(r'^\s*\[<', lines[p]):
            break
    i -= 1
  if i < 0: return False
  ind = indent(lines[i])
  s = i
  while s > 0 and (re.match(r'^\s*\[<', lines[s - 1]) and indent(lines[s - 1]) == ind or lines[s - 1].strip().startswith('//')):
    s -= 1
  e = i + 1
  while e < len(lines) and (not lines[e].strip() or indent(lines[e]) > ind):
    e += 1
  for k in range(s, e): lines[k] = ''
  # A module or type left without members does not parse: give it a placeholder.
  return True

def build(projdir, srcs):
  r = subprocess.run(['dotnet', 'build', projdir, '-c', 'Release', '-tl:off', '-v', 'q', '-nologo'],
                     capture_output=True, text=True)
  errs = {}
  for m in re.finditer(r'^(/[^(\n]+)\((\d+),\d+\): error (\w+)', r.stdout, flags=re.M):
    errs.setdefault(m.group(1), set()).add(int(m.group(2)) - 1)
  return r.returncode == 0, errs, r.stdout

def settle(projdirs, texts):
  """Build, cut what fails, until it builds. texts: abs path -> list of lines."""
  for round_ in range(40):
    ok = True
    allerrs = {}
    for pd in projdirs:
      good, errs, out = build(pd, texts)
      if round_ == 0 or not good:
        with open(os.path.join(work, 'build-errors.log'), 'a') as log: log.write(out)
      if not good:
        ok = False
        allerrs.update(errs)
        if not errs:
          sys.exit('build failed without file errors:\n' + out[-4000:])
        break
    if ok: return
    for f, lns in allerrs.items():
      f = os.path.realpath(f)
      lines = texts[f]
      for ln in sorted(lns, reverse=True):
        if lines[ln].strip():
          if not cut(lines, ln, f.endswith('.cs')):
            sys.exit(f'cannot cut {f}:{ln + 1}')
      fill_empty_modules(lines)
      open(f, 'w').write('\n'.join(lines) + '\n')
  sys.exit('did not settle')

def fill_empty_modules(lines):
  for i, l in enumerate(lines):
    if re.match(r'^\s*module .+=\s*$', l) or re.match(r'^\s*type \w+\s*=\s*$', l):
      j = i + 1
      while j < len(lines) and not lines[j].strip(): j += 1
      if j >= len(lines) or indent(lines[j]) <= indent(l):
        lines[i] = l + ' begin end' if 'module' in l else l.rstrip(' =') + ' = class end'

def write(path, text):
  os.makedirs(os.path.dirname(path), exist_ok=True)
  open(path, 'w').write(text)

texts = {}
projects = []
total = 0

def count_tests(text, cs):
  if cs:
    return len(re.findall(r'^\s*\[(Fact|Theory|Property)\b', text, flags=re.M))
  return len(re.findall(r'^\s*\[<(Property|Fact|Theory)\b', text, flags=re.M))

gen_fsproj = 'tests/OpenTK.Tests.Generators/OpenTK.Tests.Generators.fsproj'
have_gen = bool(git_ls(gen_fsproj))
if have_gen:
  d = os.path.join(work, 'gen')
  files = compile_order(gen_fsproj)
  files = [f for f in files if f != 'AssemblyInfo.fs']
  for f in files:
    p = os.path.realpath(os.path.join(d, f)); t = fix(git_show(f'tests/OpenTK.Tests.Generators/{f}'), False)
    write(p, t); texts[p] = t.split('\n')
  write(os.path.join(d, 'gen.fsproj'), project('fs', files, []).replace('<IsPackable>', '<IsTestProject>false</IsTestProject><IsPackable>'))
  projects.append(d)

d = os.path.join(work, 'fs')
files = [f for f in compile_order('tests/OpenTK.Tests/OpenTK.Tests.fsproj') if f not in ('AssemblyInfo.fs', 'KeyboardStateTest.fs')]
for f in files:
  p = os.path.realpath(os.path.join(d, f)); t = fix(git_show(f'tests/OpenTK.Tests/{f}'), False)
  total += count_tests(t, False)
  write(p, t); texts[p] = t.split('\n')
write(os.path.join(d, 'fs.fsproj'), project('fs', files, ['../gen/gen.fsproj'] if have_gen else []))
projects.append(d)

cs_files = [f for f in git_ls('tests/OpenTK.Tests.Math') if f.endswith('.cs') and '/Properties/' not in f]
if cs_files:
  d = os.path.join(work, 'cs')
  for f in cs_files:
    p = os.path.realpath(os.path.join(d, os.path.relpath(f, 'tests/OpenTK.Tests.Math'))); t = fix(git_show(f), True)
    total += count_tests(t, True)
    write(p, t); texts[p] = t.split('\n')
  write(os.path.join(d, 'cs.csproj'), project('cs', [], ['../gen/gen.fsproj'] if have_gen else []))
  projects.append(d)

settle(projects, texts)

results = {}
for pd in projects:
  if pd.endswith('gen'): continue
  trx = os.path.abspath(os.path.join(work, os.path.basename(pd) + '.trx'))
  if os.path.exists(trx): os.remove(trx)
  subprocess.run(['dotnet', 'test', pd, '-c', 'Release', '--no-build', '--logger', f'trx;LogFileName={trx}'], capture_output=True)
  for r in ET.parse(trx).getroot().iter('{http://microsoft.com/schemas/VisualStudio/TeamTest/2010}UnitTestResult'):
    name = re.sub(r'\(\w+: .*\)$', '', r.get('testName'))  # a theory's cases count as one test
    results[name] = results.get(name, True) and r.get('outcome') == 'Passed'
left = sum(count_tests('\n'.join(t), p.endswith('.cs')) for p, t in texts.items())
passed = sum(results.values())
print(f'tests in the suites: {total}; compile: {left}; run: {len(results)}; pass: {passed}; fail: {len(results) - passed}')
for n, ok in sorted(results.items()):
  if not ok: print('FAIL', n)
