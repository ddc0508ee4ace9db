using System;
using System.Collections.Generic;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// Forms of GrCis's API that changed shape over the years, in scripts and modules as students wrote them:
/// <c>BezierSurface.Epsilon</c> static (until May 2020) and per surface (since June 2020), interface members
/// an older class lacks, renderers that override <c>RenderPixel</c>.
/// </summary>
public sealed class OlderFormsTests() : ScratchScriptTests("grcis-oldforms-")
{
  // One bicubic patch, flat in z = 0, over [0, 3] × [0, 3].
  const string FlatPatch = """
    double[] net = new double[16 * 3];
    for (int i = 0; i < 16; i++)
    {
      net[3 * i] = i % 4;
      net[3 * i + 1] = i / 4;
    }
    """;

  [Fact]
  public void A_script_sets_the_Bezier_threshold_in_the_static_form_of_2018_and_the_instance_form_of_2020()
  {
    // The same value written back, so renders elsewhere in the process are not affected.
    ScriptScene run = host.Load(Write("Bezier.cs", FlatPatch + """
      double old = BezierSurface.Epsilon;   // until May 2020: static
      BezierSurface.Epsilon = old;
      var surface = new BezierSurface(1, 1, net);
      surface.Epsilon = old;                 // since June 2020: per surface, one shared threshold
      context["same"] = surface.Epsilon == BezierSurface.Epsilon;
      scene.Intersectable = new BezierSurface(1, 1, net) { Epsilon = old };
      """));
    Assert.Equal(true, run.Context["same"]);
    Assert.IsType<BezierSurface>(run.Scene.Intersectable);
  }

  [Fact]
  public void A_module_of_2020_sets_the_Bezier_threshold_per_surface()
  {
    string dir = scratch.Path + "/Module2020";
    Write("Module2020/Surfaces.cs", FlatPatch.Replace("double[] net", "    double[] net").Insert(0, """
      using Rendering;

      namespace Student2020;

      public static class Surfaces
      {
        public static BezierSurface Patch(double epsilon)
        {

      """) + """
          var s = new BezierSurface(1, 1, net);
          s.Epsilon = epsilon;
          return s;
        }
      }
      """);
    host.AddModule(dir);
    ScriptScene run = host.Load(Write("UsesModule.cs", """
      using Student2020;
      scene.Intersectable = Surfaces.Patch(BezierSurface.Epsilon);
      """));
    Assert.IsType<BezierSurface>(run.Scene.Intersectable);
  }

  [Fact]
  public void A_module_of_2018_with_a_light_solid_and_renderer_of_its_year_compiles_and_renders()
  {
    string dir = scratch.Path + "/Module2018";
    Write("Module2018/Old.cs", """
      using System;
      using System.Collections.Generic;
      using MathSupport;
      using OpenTK;
      using Rendering;

      namespace Student2018
      {
        public class MyLight : ILightSource
        {
          protected Vector3d pos;
          protected double[] intensity;

          public MyLight (Vector3d p, double i)
          {
            pos = p;
            intensity = new double[] { i, i, i };
          }

          public double[] GetIntensity (Intersection intersection, out Vector3d dir)
          {
            dir = pos - intersection.CoordWorld;
            if (Vector3d.Dot(dir, intersection.Normal) <= 0.0)
              return null;
            return intensity;
          }
        }

        public class MyBall : DefaultSceneNode, ISolid
        {
          public override LinkedList<Intersection> Intersect (Vector3d p0, Vector3d p1)
          {
            double a = Vector3d.Dot(p1, p1), b = 2.0 * Vector3d.Dot(p0, p1), c = Vector3d.Dot(p0, p0) - 1.0;
            double d = b * b - 4.0 * a * c;
            if (d <= 0.0)
              return null;
            d = Math.Sqrt(d);
            LinkedList<Intersection> result = new LinkedList<Intersection>();
            result.AddLast(Hit(p0, p1, (-b - d) / (2.0 * a), true));
            result.AddLast(Hit(p0, p1, (-b + d) / (2.0 * a), false));
            return result;
          }

          Intersection Hit (Vector3d p0, Vector3d p1, double t, bool enter)
          {
            Intersection i = new Intersection(this);
            i.T = t;
            i.Enter = i.Front = enter;
            i.CoordLocal = p0 + t * p1;
            i.NormalLocal = i.CoordLocal;
            return i;
          }

          public override void CompleteIntersection (Intersection inter)
          {
            inter.Normal = Vector3d.TransformNormalInverse(inter.NormalLocal, inter.WorldToLocal).Normalized();
          }
        }

        public class MyScene : IRayScene
        {
          public IIntersectable Intersectable { get; set; }
          public double[] BackgroundColor { get; set; }
          public ICamera Camera { get; set; }
          public ICollection<ILightSource> Sources { get; set; }
        }

        public class MyRenderer : SupersamplingImageSynthesizer
        {
          public override void RenderPixel (int x, int y, double[] color)
          {
            base.RenderPixel(x, y, color);
            color[1] = 0.5;   // a green tint over everything, in display colour
          }
        }
      }
      """);
    host.AddModule(dir);
    ScriptScene run = host.Load(Write("Scene2018.cs", """
      using Student2018;
      CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
      root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
      root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.2, 0.2 }, 0.1, 0.8, 0.1, 16));
      root.InsertChild(new MyBall(), Matrix4d.Identity);
      MyScene s = new MyScene();
      s.Intersectable = root;
      s.BackgroundColor = new double[] { 0.0, 0.0, 0.3 };
      s.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -5.0), Vector3d.UnitZ, 40.0);
      s.Sources = new List<ILightSource> { new AmbientLightSource(0.2), new MyLight(new Vector3d(-2.0, 3.0, -4.0), 1.0) };
      scene.Intersectable = root;
      context["own scene"] = s;   // a scene class of the student's own, as their project built it
      context[PropertyName.CTX_SYNTHESIZER] = new MyRenderer { Supersampling = 4 };
      """));
    var own = Assert.IsAssignableFrom<IRayScene>(run.Context["own scene"]);
    Assert.Equal("MyScene", own.GetType().Name);
    Assert.Null(own.Background);
    var renderer = Assert.IsAssignableFrom<ImageSynthesizer>(run.Synthesizer);
    Assert.Equal("MyRenderer", renderer.GetType().Name);

    // Rendered: the ball is lit by the student's light, and the image shows the renderer's display colours.
    renderer.Width = 24;
    renderer.Height = 18;
    FloatImage image = TileRenderer.Render(own, new RayTracing(own), renderer, new RenderOptions { Threads = 1 });
    double[] centre = new double[3], corner = new double[3];
    image.GetPixel(12, 9, centre);
    image.GetPixel(0, 0, corner);
    ImageSynthesizer.ApplyGamma(centre, renderer.Gamma);
    ImageSynthesizer.ApplyGamma(corner, renderer.Gamma);
    Assert.Equal(0.5, centre[1], 5);
    Assert.Equal(0.5, corner[1], 5);
    Assert.True(centre[0] > 0.5, $"lit ball, red {centre[0]}");
    Assert.Equal(0.0, corner[0], 5);
  }
}
