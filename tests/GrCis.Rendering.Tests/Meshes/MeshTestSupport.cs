using Scene3D;
using System.IO;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Meshes;

internal static class MeshTestSupport
{
  /// <summary>Shared read-only meshes of the project machine (never copied into the repository).</summary>
  public static string MeshDir => GrCis.Rendering.Tests.SharedFolder.Combine("data", "meshes");

  /// <summary>The unit cube [0,1]³ as 12 outward-oriented triangles.</summary>
  public const string CubeObj = @"# unit cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
";

  public static SceneBrep Read(string text, WavefrontObj? reader = null)
  {
    var scene = new SceneBrep();
    (reader ?? new WavefrontObj()).ReadBrep(new StringReader(text), scene);
    return scene;
  }
}
