using System.Runtime.CompilerServices;

namespace Rendering;

/// <summary>
/// Whether a scene is one of the library's own classes (<see cref="DefaultRayScene"/>, <see cref="AnimatedRayScene"/>),
/// whose <see cref="IRayScene"/> members are plain properties: the hot paths read those directly instead of through
/// the interface. Code compiled without a profile (ReadyToRun images, a render's first moments before tier 1) then makes
/// no interface call per sample, and tier-1 code needs no type guard. Any other scene (a script's own class) is read
/// through the interface, as before.
/// </summary>
internal static class LibraryScene
{
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Is(IRayScene scene) =>
    scene.GetType() == typeof(DefaultRayScene) || scene.GetType() == typeof(AnimatedRayScene);   // method-table compares
}
