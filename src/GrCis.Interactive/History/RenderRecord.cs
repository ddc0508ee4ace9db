using System;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>One remembered render: its image with the settings and statistics it was made with.</summary>
public sealed class RenderRecord
{
  public RenderRecord(FloatImage image, RenderSettings settings, RenderStatistics statistics, string? sceneName, string param, double gamma, bool complete)
  {
    Image = image ?? throw new ArgumentNullException(nameof(image));
    Settings = settings ?? throw new ArgumentNullException(nameof(settings));
    Statistics = statistics ?? throw new ArgumentNullException(nameof(statistics));
    SceneName = sceneName;
    Param = param ?? "";
    Gamma = gamma;
    Complete = complete;
  }

  public static RenderRecord From(RenderResult result)
  {
    ArgumentNullException.ThrowIfNull(result);
    return new RenderRecord(result.Image, result.Job.Settings, result.Statistics, result.Job.SceneName, result.Job.Param, result.Gamma, result.Succeeded);
  }

  /// <summary>Linear colours.</summary>
  public FloatImage Image { get; }

  public RenderSettings Settings { get; }

  public RenderStatistics Statistics { get; }

  public string? SceneName { get; }

  public string Param { get; }

  public double Gamma { get; }

  /// <summary>False for a stopped or failed render (the image has unfinished tiles).</summary>
  public bool Complete { get; }

  /// <summary>The display image (gamma applied, quantized as <c>grcis render</c> saves it).</summary>
  public Rgb8Image ToRgb8() => Rendering.Execution.RenderSetup.ToDisplayImage(Image, Gamma);

  /// <summary>Saves the display image as PNG; atomic, an existing file is replaced only by a complete one.</summary>
  /// <exception cref="ImageSaveException">The file could not be written.</exception>
  public void SavePng(string path) => PngFile.Save(path, ToRgb8());

  public override string ToString() => $"{SceneName ?? "scene"}{(Param.Length > 0 ? $" ({Param})" : "")}: {Statistics}";
}
