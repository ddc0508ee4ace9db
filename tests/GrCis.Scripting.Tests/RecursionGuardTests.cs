using System;
using System.IO;
using System.Threading;
using Rendering.Execution;

namespace GrCis.Scripting.Tests;

/// <summary>
/// User code is compiled with a recursion guard in every method, local function, accessor and lambda body, so a
/// recursion without end is a runtime error at the user's line instead of a stack overflow that kills the process.
/// </summary>
public sealed class RecursionGuardTests : IDisposable
{
  readonly ScriptHost host = new();
  readonly ScratchFolder scratch = new("grcis-recursion-");

  public void Dispose()
  {
    host.Dispose();
    scratch.Dispose();
  }

  string Write(string relative, string text) => scratch.Write(relative, text);

  static Exception? OnThread(Action run, int stackSize)
  {
    Exception? thrown = null;
    var t = new Thread(() =>
    {
      try
      {
        run();
      }
      catch (Exception e)
      {
        thrown = e;
      }
    }, stackSize);
    t.Start();
    Assert.True(t.Join(TimeSpan.FromMinutes(1)));
    return thrown;
  }

  [Theory]
  [InlineData("int F(int n) => n < 0 ? 0 : F(n + 1) + 1;\nF(0);", 1)]
  [InlineData("void F(int n)\n{\n  F(n + 1);\n}\nF(0);", 3)]
  [InlineData("int x = 1;\nSystem.Func<int, int> f = null;\nf = n => f(n + 1) + 1;\nf(0);", 3)]
  [InlineData("System.Action<int> a = null;\na = n => a(n + 1);\na(0);", 2)]
  [InlineData("var d = new Deep();\nint v = d.P;\nclass Deep\n{\n  public int P => P + 1;\n}", 5)]
  [InlineData("var d = new Deep();\nint v = d[0];\nclass Deep\n{\n  public int this[int i] { get { return this[i + 1]; } }\n}", 5)]
  [InlineData("int G(int n)\n{\n  int L(int k) => G(k + 1);\n  return L(n);\n}\nG(0);", 4)]
  public void A_recursion_without_end_is_a_runtime_error_at_the_recursive_call(string text, int line)
  {
    string path = Write("deep.cs", text + "\n");
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path));
    Assert.Equal(path, ex.Path);
    Assert.Equal(line, ex.Line);
    Assert.IsType<RecursionTooDeepException>(ex.InnerException);
    Assert.Contains($"recursion deeper than {Recursion.MaxDepth} calls", ex.Message);
  }

  [Theory]
  [InlineData("IEnumerable<int> F(int n)\n{\n  foreach (int x in F(n + 1))\n    yield return x;\n  yield return n;\n}\nforeach (int x in F(0)) { }", 3)]
  [InlineData("async System.Threading.Tasks.Task<int> F(int n) => await F(n + 1) + 1;\nawait F(0);", 1)]
  [InlineData("async System.Threading.Tasks.Task F(int n)\n{\n  await F(n + 1);\n}\nawait F(0);", 3)]
  [InlineData("System.Func<int, System.Threading.Tasks.Task<int>> f = null;\nf = async n => await f(n + 1) + 1;\nawait f(0);", 2)]
  [InlineData("System.Func<int, System.Threading.Tasks.Task> g = null;\ng = async n => { await g(n + 1); };\nawait g(0);", 2)]
  [InlineData("var d = new Deep();\nforeach (int x in d.Items) { }\nclass Deep\n{\n  public IEnumerable<int> Items { get { foreach (int x in new Deep().Items) yield return x; yield return 1; } }\n}", 5)]
  public void A_recursion_through_iterators_or_async_bodies_is_a_runtime_error_at_its_line(string text, int line)
  {
    string path = Write("deep.cs", text + "\n");
    CompiledScript script = host.Compile(path);
    // 1 MiB, about a thread pool thread's: the check leaves room for the error whatever the stack.
    Exception? e = OnThread(() => host.Run(script), 1 << 20);
    var ex = Assert.IsType<ScriptRuntimeException>(e);
    Assert.Equal(path, ex.Path);
    Assert.Equal(line, ex.Line);
    Assert.Contains("fills the thread's stack", ex.Message);
  }

  [Fact]
  public void On_a_small_stack_the_stack_left_ends_it_first()
  {
    // Big frames on a 256 KiB stack: the stack fills long before MaxDepth calls.
    string path = Write("big.cs", "double F(int n, Vector3d a, Vector3d b, Vector3d c) { var d = a + b + c; var e = d * 2; return F(n + 1, e, d, a) + d.X; }\nF(0, Vector3d.One, Vector3d.One, Vector3d.One);\n");
    CompiledScript script = host.Compile(path);
    Exception? e = OnThread(() => host.Run(script), 256 << 10);
    var ex = Assert.IsType<ScriptRuntimeException>(e);
    Assert.Equal(1, ex.Line);
    Assert.Matches("recursion deeper than [0-9]+ calls fills the thread's stack", ex.Message);
  }

  [Fact]
  public void The_count_goes_down_as_calls_return_and_as_errors_unwind()
  {
    // Three times 9000 deep, once after an error caught at 10000: a count that leaked would stop the later ones.
    string path = Write("balanced.cs", """
      int Down(int n) => n == 0 ? 0 : Down(n - 1) + 1;
      int Endless(int n) => Endless(n + 1);
      int total = Down(9000) + Down(9000);
      try { Endless(0); } catch (Rendering.Execution.RecursionTooDeepException) { total += 1; }
      System.Func<int, int> f = null;
      f = n => n == 0 ? 0 : f(n - 1) + 1;
      total += f(9000);
      context["total"] = total;
      """);
    Assert.Equal(27_001, host.Load(path).Context["total"]);
  }

  [Fact]
  public void Guarded_forms_compute_what_they_did_before()
  {
    string path = Write("forms.cs", """
      using System.Linq;
      using System.Linq.Expressions;
      using System.Threading.Tasks;
      IEnumerable<int> Gen(int n) { for (int i = 0; i < n; i++) yield return i; }
      IEnumerable<int> None() { yield break; }
      IEnumerable<int> Tree(int n) { if (n > 0) foreach (int x in Tree(n - 1)) yield return x + 1; else yield return 0; }
      async Task<int> Later(int n) { await Task.Yield(); return n * 2; }
      async Task<int> Sooner(int n) => n == 0 ? 0 : await Sooner(n - 1) + 1;
      async Task Nap() => await Task.Yield();
      async ValueTask<int> Value2() { await Task.Yield(); return 2; }
      Func<int, Task<int>> lazy = async n => await Later(n) + 1;
      Func<Task> napping = async () => await Task.Yield();
      napping().Wait();
      Nap().Wait();
      static int Twice(int n) => n * 2;
      void Nothing() { }
      void Fail() => throw new InvalidOperationException("no");
      int Value() => throw new InvalidOperationException("no");
      Expression<Func<int, int>> tree = x => Math.Abs(x) + Twice(x);
      Func<int, int> compiled = tree.Compile();
      Action<int> act = n => Nothing();
      act(1);
      var box = new Box(3);
      box.Value = 4;
      int sum = Gen(4).Sum() + None().Count() + Tree(100).Single() - 100 + Sooner(300).Result - 300 + Value2().Result - 2 + lazy(1).Result - 3 +
                Later(5).Result + compiled(-2) + box.Value + box.Doubled + box[2] + (int)(new Box(1) + new Box(2)).Value;
      try { Fail(); } catch (InvalidOperationException) { sum += 1000; }
      try { Value(); } catch (InvalidOperationException) { sum += 1000; }
      ref int First(int[] a) => ref a[0];
      int[] arr = { 7 };
      First(arr) = 8;
      context["sum"] = sum + arr[0];
      class Box
      {
        int v;
        public Box(int v) => this.v = v;
        public int Value { get => v; set => v = value; }
        public int Doubled => v * 2;
        public int this[int i] => v * i;
        public static Box operator +(Box a, Box b) => new Box(a.v + b.v);
        public static explicit operator int(Box b) { return b.v; }
        ~Box() { }
      }
      """);
    // 6 + 10 - 2 + 4 + 8 + 8 + 3 + 2000 + 8
    Assert.Equal(2045, host.Load(path).Context["sum"]);
  }

  [Fact]
  public void A_recursion_in_a_module_is_an_error_at_the_module_line()
  {
    string file = Write("module/Fractal.cs", """
      namespace Deep
      {
        public static class Fractal
        {
          public static int Level(int n)
          {
            return Level(n + 1) + 1;
          }
        }
      }
      """);
    host.AddModule(Path.Combine(scratch.Path, "module"));
    string path = Write("uses.cs", "Deep.Fractal.Level(0);\n");
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path));
    Assert.Equal(file, ex.Path);
    Assert.Equal(7, ex.Line);
    Assert.Contains("recursion deeper than", ex.Message);
  }
}
