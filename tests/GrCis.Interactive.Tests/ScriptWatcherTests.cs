using System;
using System.IO;
using System.Threading;
using System.Threading.Tasks;

namespace GrCis.Interactive.Tests;

public class ScriptWatcherTests
{
  static readonly TimeSpan Wait = TimeSpan.FromSeconds(10);

  [Theory]
  [InlineData(true)]
  [InlineData(false)] // polling alone
  public async Task Editing_the_file_raises_one_change(bool useFileSystemWatcher)
  {
    using var tmp = new TempDir();
    string path = tmp.File("scene.cs");
    File.WriteAllText(path, "// v1");
    using var watcher = new ScriptWatcher(path, TimeSpan.FromMilliseconds(100), TimeSpan.FromMilliseconds(200), useFileSystemWatcher);
    int count = 0;
    var first = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
    watcher.Changed += (_, e) => { Interlocked.Increment(ref count); Assert.Equal(path, e.Path); first.TrySetResult(); };

    File.WriteAllText(path, "// v2, longer");
    await first.Task.WaitAsync(Wait);
    await Task.Delay(700); // watcher and poller both noticed; the hash lets only one through
    Assert.Equal(1, Volatile.Read(ref count));
  }

  [Fact]
  public async Task Touching_without_changing_content_is_ignored()
  {
    using var tmp = new TempDir();
    string path = tmp.File("scene.cs");
    File.WriteAllText(path, "// same");
    using var watcher = new ScriptWatcher(path, TimeSpan.FromMilliseconds(50), TimeSpan.FromMilliseconds(100));
    int count = 0;
    watcher.Changed += (_, _) => Interlocked.Increment(ref count);
    File.WriteAllText(path, "// same");
    File.SetLastWriteTimeUtc(path, DateTime.UtcNow.AddSeconds(5));
    await Task.Delay(800);
    Assert.Equal(0, Volatile.Read(ref count));
  }
}
