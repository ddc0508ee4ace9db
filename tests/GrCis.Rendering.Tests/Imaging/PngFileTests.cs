using System;
using System.IO;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public sealed class PngFileTests : IDisposable
{
  private readonly string _dir = Directory.CreateTempSubdirectory("png-file-test-").FullName;

  public void Dispose() => Directory.Delete(_dir, recursive: true);

  [Fact]
  public void SaveLoadRoundTripLeavesOnlyTheTarget()
  {
    string path = Path.Combine(_dir, "img.png");
    Rgb8Image img = PngTestFiles.RandomImage(7, 3, 1);
    PngFile.Save(path, img);
    Assert.True(img.ContentEquals(PngFile.Load(path)));
    Assert.Equal(new[] { path }, Directory.GetFiles(_dir));
  }

  [Fact]
  public void SaveOverwritesExistingFile()
  {
    string path = Path.Combine(_dir, "img.png");
    File.WriteAllText(path, "old");
    FloatImage f = new(2, 2);
    f.SetPixel(1, 1, [1, 0.5, 0]);
    PngFile.Save(path, f, gamma: 1.0);
    Assert.Equal((255, 128, 0), ((int, int, int))PngFile.Load(path).GetPixel(1, 1));
    Assert.Single(Directory.GetFiles(_dir));
  }

  [Fact]
  public void MissingDirectoryThrowsAndCreatesNothing()
  {
    string missing = Path.Combine(_dir, "no-such-dir");
    string path = Path.Combine(missing, "img.png");
    var ex = Assert.Throws<ImageSaveException>(() => PngFile.Save(path, new Rgb8Image(1, 1)));
    Assert.IsAssignableFrom<IOException>(ex);
    Assert.Contains(path, ex.Message);
    Assert.Equal(path, ex.Path);
    Assert.False(Directory.Exists(missing));
    Assert.Empty(Directory.GetFileSystemEntries(_dir));
  }

  [Fact]
  public void TargetThatIsADirectoryIsNotClobbered()
  {
    string path = Path.Combine(_dir, "taken");
    Directory.CreateDirectory(path);
    File.WriteAllText(Path.Combine(path, "keep.txt"), "x");
    Assert.Throws<ImageSaveException>(() => PngFile.Save(path, new Rgb8Image(1, 1)));
    Assert.True(File.Exists(Path.Combine(path, "keep.txt")));
    Assert.Equal(new[] { path }, Directory.GetFileSystemEntries(_dir));
  }

  [Fact]
  public void FailureMidWriteKeepsOldTargetAndRemovesTemp()
  {
    string path = Path.Combine(_dir, "img.png");
    File.WriteAllText(path, "previous good image");
    var ex = Assert.Throws<ImageSaveException>(() => AtomicFile.Write(path, s =>
    {
      s.Write(new byte[1000]);
      throw new IOException("disk full");
    }));
    Assert.Contains("disk full", ex.Message);
    Assert.Equal("previous good image", File.ReadAllText(path));
    Assert.Single(Directory.GetFiles(_dir));
  }

  [Fact]
  public void NonIoFailureIsRethrownUnwrappedAndTempRemoved()
  {
    string path = Path.Combine(_dir, "img.png");
    Assert.Throws<InvalidOperationException>(() => AtomicFile.Write(path, _ => throw new InvalidOperationException("bug")));
    Assert.Empty(Directory.GetFileSystemEntries(_dir));
  }

  [Fact]
  public void LoadOfCorruptFileNamesThePath()
  {
    string path = Path.Combine(_dir, "bad.png");
    File.WriteAllBytes(path, [1, 2, 3]);
    Assert.Contains(path, Assert.Throws<InvalidDataException>(() => PngFile.Load(path)).Message);
  }

  [Fact]
  public void InvalidArgumentsFailBeforeTouchingDisk()
  {
    Assert.Throws<ArgumentException>(() => PngFile.Save("", new Rgb8Image(1, 1)));
    Assert.Throws<ArgumentOutOfRangeException>(() => PngFile.Save(Path.Combine(_dir, "g.png"), new FloatImage(1, 1), gamma: 0));
    Assert.Empty(Directory.GetFileSystemEntries(_dir));
  }
}
