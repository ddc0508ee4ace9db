using System;

namespace Rendering;

/// <summary>What a scene class written before GrCis added a member answers when that member is set.</summary>
static class OlderScene
{
  /// <summary>Null is what such a scene already has; anything else would be lost, so it is an error that says why.</summary>
  public static void Refuse(IRayScene scene, string member, object? value)
  {
    if (value != null)
      throw new NotSupportedException(
        $"{scene.GetType().Name} implements IRayScene without {member} (written before GrCis had it), so it cannot take one; " +
        $"add a '{member} {{ get; set; }}' property to it or derive it from DefaultRayScene.");
  }
}
