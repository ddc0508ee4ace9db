using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A scene's animator: named properties (<see cref="Property{T}"/>) interpolated by uniform
/// Catmull–Rom splines at the current <see cref="Time"/>. Scene objects ask for values by name
/// (usually through <c>MT.scene.Animator</c>) when their own time is set, which is why the
/// animated scene gives time to its animator first.
/// </summary>
/// <remarks>
/// Animators can be chained: <c>nextGeneral</c> receives the same time, <c>nextProperty</c>
/// answers names this animator does not know. <see cref="Clone"/> copies the time and shares
/// the property data (read-only after set-up).
/// </remarks>
[Serializable]
public partial class PropertyAnimator : ITimeDependentProperty
{
  /// <summary>Next general animator of the chain (receives Start, End and Time).</summary>
  protected ITimeDependent? nextGeneral;

  /// <summary>Next property animator of the chain (also answers unknown names).</summary>
  protected ITimeDependentProperty? nextProperty;

  /// <summary>Property name → <see cref="Property{T}"/>; shared by clones.</summary>
  protected Dictionary<string, object> properties = new();

  /// <summary>Start of the time range (<see cref="Start"/>).</summary>
  protected double start;
  /// <summary>End of the time range (<see cref="End"/>).</summary>
  protected double end = 10.0;
  /// <summary>The current time (<see cref="Time"/>); −∞ until it is first set.</summary>
  protected double time = double.NegativeInfinity;

  /// <summary>An animator without properties, time range 0 to 10 s; add properties with <see cref="newProperty{T}"/>.</summary>
  /// <param name="nxtGen">Next general animator of the chain (receives the same times), or null.</param>
  /// <param name="nxtProp">Next property animator of the chain (receives the same times, answers unknown names), or null.</param>
  public PropertyAnimator(in ITimeDependent? nxtGen = null, in ITimeDependentProperty? nxtProp = null)
  {
    nextGeneral = nxtGen;
    nextProperty = nxtProp;
    Start = 0.0;
    End = 10.0;
  }

  /// <summary>Start of the time range in seconds; setting it sets the chain's too.</summary>
  public double Start
  {
    get => start;
    set
    {
      if (nextGeneral != null)
        nextGeneral.Start = value;
      if (nextProperty != null)
        nextProperty.Start = value;
      start = value;
    }
  }

  /// <summary>End of the time range in seconds; setting it sets the chain's too.</summary>
  public double End
  {
    get => end;
    set
    {
      if (nextGeneral != null)
        nextGeneral.End = value;
      if (nextProperty != null)
        nextProperty.End = value;
      end = value;
    }
  }

  /// <summary>Current time in seconds, clamped to [Start, End]; setting it sets the chain's too.</summary>
  public double Time
  {
    get => time;
    set
    {
      if (nextGeneral != null)
        nextGeneral.Time = value;
      if (nextProperty != null)
        nextProperty.Time = value;
      setTime(value);
    }
  }

  /// <summary>Stores the new time, clamped to [Start, End]. Override to do more when time changes.</summary>
  protected virtual void setTime(double newTime) => time = Math.Clamp(newTime, Math.Min(start, end), Math.Max(start, end));

  /// <summary>A copy with its own time (and its own chain), sharing the property data.</summary>
  public virtual object Clone()
  {
    var a = (PropertyAnimator)MemberwiseClone();
    a.nextGeneral = (ITimeDependent?)nextGeneral?.Clone();
    a.nextProperty = (ITimeDependentProperty?)nextProperty?.Clone();
    return a;
  }

  /// <summary>Adds or replaces a property.</summary>
  public virtual void setProperty<T>(in Property<T> property)
  {
    ArgumentNullException.ThrowIfNull(property);
    if (string.IsNullOrEmpty(property.name))
      throw new ArgumentException("A property needs a non-empty name.", nameof(property));
    properties[property.name] = property;
  }

  /// <summary>Creates and adds a property (see <see cref="Property{T}"/> for the meaning of the arguments).</summary>
  public virtual void newProperty<T>(
    in string name,
    in double start,
    in double end,
    in double period,
    in InterpolationStyle style,
    List<T> data,
    bool cyclic = false)
  {
    setProperty(new Property<T>
    {
      name = name,
      tStart = start,
      tEnd = end,
      tPeriod = period,
      style = style,
      data = data,
      cyclic = cyclic,
    });
  }

  /// <summary>Names of the properties this animator (not its chain) holds.</summary>
  public IEnumerable<string> PropertyNames => properties.Keys;

  /// <summary>Current value of any supported property type (boxed; arrays are new arrays), or null.</summary>
  public virtual object? GetValue(in string name)
  {
    if (!properties.TryGetValue(name, out object? p))
      return nextProperty?.GetValue(name);
    double t = time;
    return p switch
    {
      Property<double> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<float> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector3d> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector4d> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector3> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector4> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Quaterniond> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Matrix4d> q => Eval(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<double[]> q => EvalArray(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector3d[]> q => EvalArray(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector4d[]> q => EvalArray(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector3[]> q => EvalArray(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      Property<Vector4[]> q => EvalArray(q, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f)),
      _ => null,
    };
  }

  /// <summary>The named double or float property's current value; false (and <paramref name="d"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="d">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref double d)
  {
    if (properties.TryGetValue(name, out object? p))
    {
      if (p is Property<double> pd && TryEval(pd, time, out double v))
      {
        d = v;
        return true;
      }
      if (p is Property<float> pf && TryEval(pf, time, out float vf))
      {
        d = vf;
        return true;
      }
    }
    return nextProperty?.TryGetValue(name, ref d) ?? false;
  }

  /// <summary>The named double or float property's current value; false (and <paramref name="f"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="f">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref float f)
  {
    double d = f;
    if (properties.TryGetValue(name, out object? p) && (p is Property<double> || p is Property<float>) && TryGetValue(name, ref d))
    {
      f = (float)d;
      return true;
    }
    return nextProperty?.TryGetValue(name, ref f) ?? false;
  }

  /// <summary>The named Vector3d or Vector3 property's current value; false (and <paramref name="v3"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="v3">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Vector3d v3)
  {
    if (properties.TryGetValue(name, out object? p))
    {
      if (p is Property<Vector3d> pd && TryEval(pd, time, out Vector3d v))
      {
        v3 = v;
        return true;
      }
      if (p is Property<Vector3> pf && TryEval(pf, time, out Vector3 vf))
      {
        v3 = vf;
        return true;
      }
    }
    return nextProperty?.TryGetValue(name, ref v3) ?? false;
  }

  /// <summary>The named Vector3d or Vector3 property's current value; false (and <paramref name="v3"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="v3">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Vector3 v3)
  {
    Vector3d d = v3;
    if (properties.TryGetValue(name, out object? p) && (p is Property<Vector3d> || p is Property<Vector3>) && TryGetValue(name, ref d))
    {
      v3 = (Vector3)d;
      return true;
    }
    return nextProperty?.TryGetValue(name, ref v3) ?? false;
  }

  /// <summary>The named Vector4d or Vector4 property's current value; false (and <paramref name="v4"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="v4">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Vector4d v4)
  {
    if (properties.TryGetValue(name, out object? p))
    {
      if (p is Property<Vector4d> pd && TryEval(pd, time, out Vector4d v))
      {
        v4 = v;
        return true;
      }
      if (p is Property<Vector4> pf && TryEval(pf, time, out Vector4 vf))
      {
        v4 = vf;
        return true;
      }
    }
    return nextProperty?.TryGetValue(name, ref v4) ?? false;
  }

  /// <summary>The named Vector4d or Vector4 property's current value; false (and <paramref name="v4"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="v4">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Vector4 v4)
  {
    Vector4d d = v4;
    if (properties.TryGetValue(name, out object? p) && (p is Property<Vector4d> || p is Property<Vector4>) && TryGetValue(name, ref d))
    {
      v4 = (Vector4)d;
      return true;
    }
    return nextProperty?.TryGetValue(name, ref v4) ?? false;
  }

  /// <summary>The named quaternion property's current value (interpolated on the unit sphere); false (and <paramref name="q"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="q">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Quaterniond q)
  {
    if (properties.TryGetValue(name, out object? p) && p is Property<Quaterniond> pq && TryEval(pq, time, out Quaterniond v))
    {
      q = v;
      return true;
    }
    return nextProperty?.TryGetValue(name, ref q) ?? false;
  }

  /// <summary>The named matrix property's current value; false (and <paramref name="m4"/> unchanged) when neither this animator nor its chain has one.</summary>
  /// <param name="name">The property's name.</param>
  /// <param name="m4">Receives the value.</param>
  public virtual bool TryGetValue(in string name, ref Matrix4d m4)
  {
    if (properties.TryGetValue(name, out object? p) && p is Property<Matrix4d> pm && TryEval(pm, time, out Matrix4d v))
    {
      m4 = v;
      return true;
    }
    return nextProperty?.TryGetValue(name, ref m4) ?? false;
  }

  static bool TryEval(Property<double> p, double t, out double v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<float> p, double t, out float v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Vector3d> p, double t, out Vector3d v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Vector3> p, double t, out Vector3 v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Vector4d> p, double t, out Vector4d v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Vector4> p, double t, out Vector4 v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Quaterniond> p, double t, out Quaterniond v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval(Property<Matrix4d> p, double t, out Matrix4d v) =>
    TryEval(p, t, static (a, b, c, d, f) => CatmullRom.Interpolate(a, b, c, d, f), out v);

  static bool TryEval<T>(Property<T> p, double t, Func<T, T, T, T, double, T> interpolate, out T value)
  {
    if (!p.prepareCubic(t, out double f, out int i0, out int i1, out int i2, out int i3))
    {
      value = default!;
      return false;
    }
    List<T> k = p.data!;
    value = interpolate(k[i0], k[i1], k[i2], k[i3], f);
    return true;
  }

  static object? Eval<T>(Property<T> p, double t, Func<T, T, T, T, double, T> interpolate) where T : struct =>
    TryEval(p, t, interpolate, out T v) ? v : null;

  /// <summary>Element-wise interpolation of array-valued knots (the shortest knot decides the length).</summary>
  static object? EvalArray<T>(Property<T[]> p, double t, Func<T, T, T, T, double, T> interpolate)
  {
    if (!p.prepareCubic(t, out double f, out int i0, out int i1, out int i2, out int i3))
      return null;
    List<T[]> k = p.data!;
    T[] a = k[i0], b = k[i1], c = k[i2], d = k[i3];
    int n = Math.Min(Math.Min(a.Length, b.Length), Math.Min(c.Length, d.Length));
    var result = new T[n];
    for (int i = 0; i < n; i++)
      result[i] = interpolate(a[i], b[i], c[i], d[i], f);
    return result;
  }
}
