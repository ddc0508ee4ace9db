namespace Rendering.Imaging;

/// <summary>How a [0, 1] channel value becomes a byte.</summary>
public enum Quantization
{
  /// <summary>Nearest byte: (int)(v · 255 + 0.5).</summary>
  Round,

  /// <summary>GrCis's conversion, (int)(v · 255): old renders compare bit for bit.</summary>
  Truncate,
}
