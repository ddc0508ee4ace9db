using System;

namespace GrCis.Mathematics.Generators;

/// <summary>One generated source file: its hint name and text. Compared by value, so unchanged input writes nothing anew.</summary>
internal sealed class GeneratedFile : IEquatable<GeneratedFile>
{
  public GeneratedFile(string hintName, string text)
  {
    HintName = hintName;
    Text = text;
  }

  public string HintName { get; }

  public string Text { get; }

  public bool Equals(GeneratedFile? other) =>
    other is not null && string.Equals(HintName, other.HintName, StringComparison.Ordinal) && string.Equals(Text, other.Text, StringComparison.Ordinal);

  public override bool Equals(object? obj) => Equals(obj as GeneratedFile);

  public override int GetHashCode() => StringComparer.Ordinal.GetHashCode(HintName) ^ StringComparer.Ordinal.GetHashCode(Text);
}
