using System;
using System.IO;
using Rendering.Execution;

namespace GrCis.Cli.Tests;

public class ErrorMessagesTests
{
  /// <summary>Shaped like the mesh loader's format error: file and line as properties.</summary>
  sealed class FakeMeshFormatException : FormatException
  {
    public FakeMeshFormatException(string fileName, int line, string message) : base(message)
    {
      FileName = fileName;
      Line = line;
    }

    public string FileName { get; }
    public int Line { get; }
  }

  /// <summary>Shaped like Rendering.MeshFormatException: LineNumber, and the location already in the message.</summary>
  sealed class LocatedMessageException : FormatException
  {
    public LocatedMessageException(string fileName, int lineNumber, string problem) : base($"{fileName}({lineNumber}): {problem}")
    {
      FileName = fileName;
      LineNumber = lineNumber;
    }

    public string FileName { get; }
    public int LineNumber { get; }
  }

  [Fact]
  public void Mesh_format_error_with_line_number_prints_its_location_once()
  {
    var e = new RenderException("Rendering failed", new LocatedMessageException("cube.obj", 9, "vertex index 12 out of range"));
    Assert.Equal("cube.obj(9): vertex index 12 out of range", ErrorMessages.OneLine(e));
  }

  [Fact]
  public void Malformed_obj_line_prints_as_file_line_message()
  {
    var e = new FakeMeshFormatException("models/bunny.obj", 17, "face index 0 is not allowed");
    Assert.Equal("models/bunny.obj(17): face index 0 is not allowed", ErrorMessages.OneLine(e));
  }

  [Fact]
  public void Location_is_found_inside_wrapping_exceptions()
  {
    var inner = new FakeMeshFormatException("m.obj", 3, "bad vertex");
    var e = new RenderException("Rendering failed: bad vertex", new InvalidOperationException("scene setup", inner));
    Assert.Equal("m.obj(3): bad vertex", ErrorMessages.OneLine(e));
  }

  [Fact]
  public void Location_already_in_the_message_is_not_repeated()
  {
    var e = new FakeMeshFormatException("m.obj", 3, "m.obj(3): bad vertex");
    Assert.Equal("m.obj(3): bad vertex", ErrorMessages.OneLine(e));
  }

  [Fact]
  public void Multi_line_messages_become_one_line()
  {
    Assert.Equal("first second", ErrorMessages.OneLine(new IOException("first\nsecond\n")));
  }

  [Fact]
  public void Exceptions_without_location_print_their_message()
  {
    Assert.Equal("disk full", ErrorMessages.OneLine(new IOException("disk full")));
  }
}
