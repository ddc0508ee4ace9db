using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

public partial class Scenes
{
  /// <summary>
  /// The 049 distributed ray tracing "Test scene": a shiny sphere on a checkered plane lit by a tall, thin
  /// rectangle light (a vertical "stick", dimmed with distance) and ambient light. Meant for
  /// <see cref="Distributed.DistributedRayTracing"/> with 16 or more samples per pixel: soft shadows and glossy reflections.
  /// </summary>
  public static void TestScene(IRayScene sc)
  {
    // GrCis's 049 sets the root material twice; the second (ks 0.7, h 16) is the one that renders.
    CSGInnerNode root = Root(sc, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.3, 0.7, 16));
    sc.BackgroundColor = new[] { 0.0, 0.05, 0.07 };
    sc.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.28, 1.0), 50.0);

    var stick = new RectangleLightSource(new Vector3d(-5.0, 1.0, -3.0), new Vector3d(0.0, 0.0, 0.1), new Vector3d(0.0, 6.0, 0.0), 1.8)
    {
      Dim = new[] { 1.0, 0.05, 0.0 },
    };
    sc.Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.8), stick });

    root.InsertChild(new Sphere(), Matrix4d.Identity);
    Floor(root, new[] { 0.3, 0.0, 0.0 }, 0.6, new[] { 1.0, 1.0, 1.0 });
  }
}
