using System;
using System.Diagnostics;
using System.IO;
using System.Threading;
using Rendering.Execution;

namespace GrCis.Scripting.Tests;

/// <summary>
/// User code is compiled with an interruption point in every loop and before every goto, so a host can
/// stop a script stuck in an endless loop; positions in messages stay those of the file as written.
/// </summary>
public sealed class InterruptionTests : IDisposable
{
  readonly ScriptHost host = new();
  readonly ScratchFolder scratch = new("grcis-interrupt-");

  public void Dispose()
  {
    host.Dispose();
    scratch.Dispose();
  }

  string Write(string relative, string text) => scratch.Write(relative, text);

  /// <summary>Runs the script on a thread whose token is cancelled 200 ms after the script started.</summary>
  static Exception? RunAndStop(Action run)
  {
    using var cts = new CancellationTokenSource();
    Exception? thrown = null;
    var worker = new Thread(() =>
    {
      using Interruption.Scope scope = Interruption.Use(cts.Token);
      try
      {
        run();
      }
      catch (Exception e)
      {
        thrown = e;
      }
    }) { IsBackground = true };
    worker.Start();
    Thread.Sleep(200);
    var clock = Stopwatch.StartNew();
    cts.Cancel();
    Assert.True(worker.Join(TimeSpan.FromSeconds(10)), "the script did not stop within 10 s of the cancellation");
    Assert.True(clock.Elapsed < TimeSpan.FromSeconds(2), $"stopping took {clock.Elapsed.TotalSeconds:0.0} s");
    return thrown;
  }

  [Theory]
  [InlineData("while (true) { }")]
  [InlineData("for (;;) ;")]
  [InlineData("int i = 0; do i++; while (i >= 0 || true);")]
  [InlineData("again: goto again;")]
  [InlineData("IEnumerable<int> Forever() { while (true) yield return 1; } foreach (int k in Forever()) { }")]
  [InlineData("void Spin() { while (true) { } } Spin();")]
  [InlineData("System.Func<int> f = () => { int n = 0; for (;;) n++; }; f();")]
  public void A_script_stuck_in_an_endless_loop_stops_when_its_token_is_cancelled(string loop)
  {
    string path = Write("stuck.cs", loop + "\n");
    CompiledScript script = host.Compile(path);
    Exception? e = RunAndStop(() => host.Run(script));
    Assert.IsType<OperationCanceledException>(e);
  }

  [Fact]
  public void A_module_class_stuck_in_a_loop_stops_too()
  {
    Write("module/Spinner.cs", """
      namespace Spinning
      {
        public static class Spinner
        {
          public static void Spin() { int n = 0; while (n >= 0) n = (n + 1) % 7; }
        }
      }
      """);
    host.AddModule(Path.Combine(scratch.Path, "module"));
    string path = Write("uses.cs", "Spinning.Spinner.Spin();\n");
    // Compiled first (as the loops above): the compiler does not look at the token, and its time is not the stop's.
    CompiledScript script = host.Compile(path);
    Exception? e = RunAndStop(() => host.Run(script));
    Assert.IsType<OperationCanceledException>(e);
  }

  [Fact]
  public void Loops_and_gotos_compute_what_they_did_before()
  {
    string path = Write("loops.cs", """
      int sum = 0;
      for (int i = 0; i < 10; i++) sum += i;
      int j = 0; while (j < 5) j++;
      do sum++; while (sum < 50);
      foreach (int k in new[] { 1, 2, 3 }) sum += k;
      int g = 0;
      again: g++; if (g < 4) goto again;
      switch (g) { case 4: goto case 5; case 5: sum += 100; break; }
      context["sum"] = sum;
      context["counts"] = j * 10 + g;
      """);
    ScriptScene run = host.Load(path);
    Assert.Equal(156, run.Context["sum"]);
    Assert.Equal(54, run.Context["counts"]);
  }

  [Fact]
  public void Without_a_cancelled_token_the_loop_runs_to_its_end()
  {
    string path = Write("long.cs", "long n = 0; for (int i = 0; i < 50_000_000; i++) n += i & 1; context[\"n\"] = n;\n");
    using var cts = new CancellationTokenSource();
    using (Interruption.Use(cts.Token))
      Assert.Equal(25_000_000L, host.Load(path).Context["n"]);
  }

  [Fact]
  public void A_compile_error_after_a_loop_on_the_same_line_keeps_its_column()
  {
    const string line = "while (false) { } int x = \"text\";";
    string path = Write("column.cs", "// first line\n" + line + "\n");
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    ScriptDiagnostic error = Assert.Single(ex.Errors);
    Assert.Equal(2, error.Line);
    Assert.Equal(line.IndexOf("\"text\"", StringComparison.Ordinal) + 1, error.Column);
  }

  [Fact]
  public void A_runtime_error_after_a_loop_on_the_same_line_keeps_its_column()
  {
    const string line = "for (int i = 0; i < 2; i++) { } int[] a = new int[1]; a[3] = 1;";
    string path = Write("runtime.cs", "int z = 0;\n" + line + "\n");
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path));
    Assert.Equal(2, ex.Line);
    Assert.Equal(line.IndexOf("a[3]", StringComparison.Ordinal) + 1, ex.Column);
  }
}
