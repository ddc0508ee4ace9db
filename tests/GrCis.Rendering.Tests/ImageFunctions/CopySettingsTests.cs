using System;
using System.Linq;
using System.Reflection;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>
/// <see cref="RayCasting.CopySettingsFrom"/> is the one place a copy of an image function takes its
/// settings from (demo instrumentation, per-frame animation copies): a public setting added to
/// RayCasting or RayTracing and not copied there fails this test.
/// </summary>
public class CopySettingsTests
{
  static FieldInfo[] Settings(Type t) =>
    t.GetFields(BindingFlags.Instance | BindingFlags.Public)
     .Where(f => !f.IsInitOnly && (f.DeclaringType == typeof(RayCasting) || f.DeclaringType == typeof(RayTracing)))
     .ToArray();

  /// <summary>A value of the field's type that differs from <paramref name="current"/>.</summary>
  static object Different(Type type, object? current) => type switch
  {
    _ when type == typeof(bool) => !(bool)current!,
    _ when type == typeof(int) => (int)current! + 7,
    _ when type == typeof(double) => (double)current! * 3 + 0.25,
    _ when type.IsEnum => Enum.GetValues(type).Cast<object>().First(v => !v.Equals(current)),
    _ when type == typeof(AbstractRayRegisterer) => new NullRegisterer(),
    _ => throw new InvalidOperationException($"CopySettingsTests does not know how to vary a {type.Name} setting; extend Different()"),
  };

  sealed class NullRegisterer : AbstractRayRegisterer
  {
    public override void RegisterRay(RayType rayType, params object[] parameters)
    {
    }
  }

  [Fact]
  public void Every_public_setting_of_RayTracing_is_copied()
  {
    var source = new RayTracing();
    FieldInfo[] fields = Settings(typeof(RayTracing));
    Assert.Contains(fields, f => f.Name == nameof(RayTracing.TransparentShadows));
    Assert.Contains(fields, f => f.Name == nameof(RayCasting.Accel));
    foreach (FieldInfo f in fields)
      f.SetValue(source, Different(f.FieldType, f.GetValue(source)));

    var copy = new RayTracing();
    copy.CopySettingsFrom(source);

    foreach (FieldInfo f in fields)
      Assert.True(Equals(f.GetValue(source), f.GetValue(copy)), $"RayTracing.{f.Name} is not copied by CopySettingsFrom");
  }

  [Fact]
  public void RayCasting_source_copies_the_shared_settings_and_keeps_the_rest()
  {
    var source = new RayCasting { Accel = AccelMode.None, ReuseIntersections = false };
    var copy = new RayTracing { MaxLevel = 3 };
    copy.CopySettingsFrom(source);
    Assert.Equal(AccelMode.None, copy.Accel);
    Assert.False(copy.ReuseIntersections);
    Assert.Equal(3, copy.MaxLevel);
  }
}
