using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

/// <summary>Shared log of which part received time, in order.</summary>
internal sealed class TimeLog
{
  public readonly List<string> Entries = new();
}

internal class RecordingAnimator : ITimeDependent
{
  readonly TimeLog log;
  double time;
  public RecordingAnimator(TimeLog log) => this.log = log;
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get => time; set { time = value; log.Entries.Add("animator"); } }
  public object Clone() => MemberwiseClone();
}

internal sealed class RecordingNode : DefaultSceneNode, ITimeDependent
{
  readonly TimeLog log;
  double time;
  public RecordingNode(TimeLog log) => this.log = log;
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get => time; set { time = value; log.Entries.Add("intersectable"); } }
  public object Clone() => MemberwiseClone();
}

internal sealed class RecordingBackground : IBackground, ITimeDependent
{
  readonly TimeLog log;
  double time;
  public RecordingBackground(TimeLog log) => this.log = log;
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get => time; set { time = value; log.Entries.Add("background"); } }
  public object Clone() => MemberwiseClone();
  public long GetColor(Vector3d p1, double[] color) => 0L;
}

internal sealed class RecordingCamera : StaticCamera, ITimeDependent
{
  readonly TimeLog log;
  double time;
  public RecordingCamera(TimeLog log) : base(Vector3d.Zero, Vector3d.UnitZ, 60.0) => this.log = log;
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get => time; set { time = value; log.Entries.Add("camera"); } }
  public object Clone() => MemberwiseClone();
}

internal sealed class RecordingLight : ILightSource, ITimeDependent
{
  readonly TimeLog log;
  readonly string name;
  double time;
  public RecordingLight(TimeLog log, string name)
  {
    this.log = log;
    this.name = name;
  }
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get => time; set { time = value; log.Entries.Add(name); } }
  public object Clone() => MemberwiseClone();
  public Vector3d? position { get; set; }
  public double[]? GetIntensity(Intersection intersection, out Vector3d dir)
  {
    dir = Vector3d.Zero;
    return null;
  }
}
