using System;
using System.Collections.Generic;
using System.Windows.Forms;
using GrCis.Interactive;

namespace GrCis.Demo.WinForms;

/// <summary>
/// <c>grcis-demo [-dir DIR]… [-scene FILE]… [-nodefault] [-render-to FILE]</c>: GrCis's ray-tracing demo window.
/// Everything but the drawing lives in <see cref="DemoController"/> (GrCis.Interactive).
/// </summary>
static class Program
{
  [STAThread]
  static int Main(string[] args)
  {
    Application.SetHighDpiMode(HighDpiMode.SystemAware);
    Application.EnableVisualStyles();
    Application.SetCompatibleTextRenderingDefault(false);

    // Compiled scripts are kept between sessions in the platform's cache folder (GRCIS_NO_CACHE=1: not).
    using var scripts = new GrCis.Scripting.ScriptHost(diskCache: GrCis.Scripting.Caching.ScriptCache.FromEnvironment());
    var problems = new List<string>();
    using DemoController controller = DemoController.FromCommandLine(args, scripts, problems);
    using var form = new MainForm(controller);
    if (problems.Count > 0)
      form.Shown += (_, _) => MessageBox.Show(form, string.Join(Environment.NewLine, problems), "GrCis demo: command line",
        MessageBoxButtons.OK, MessageBoxIcon.Warning);
    Application.Run(form);
    return 0;
  }
}
