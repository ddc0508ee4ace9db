using System;
using System.Collections.Generic;
using System.Globalization;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering.Tessellation;

/// <summary>
/// Turns a scene into triangles, lights and a camera for viewers outside the ray tracer (glTF export, the studio's 3D
/// view). The scene graph is walked as the renderer walks it: from the root's children down, each node placed by the
/// product of the <c>ToParent</c> matrices up to the root (the root's own is ignored, as rays enter it in world space);
/// colours and materials are inherited through <see cref="ISceneNode.GetAttribute"/>, as a hit resolves them.
/// </summary>
/// <remarks>
/// Library solids become their surfaces: the unit sphere as a UV sphere, the cube, the cylinder (an infinite one cut
/// to the scene's bounds), the torus, the plane (an infinite one as a patch around the scene's bounds), each Bézier
/// patch as a grid, a triangle mesh as its own triangles. CSG is shown as its leaves, each tagged with the operation it
/// is an operand of. A solid of a script's own class becomes its bounding box (<see cref="PartKind.BoundingBox"/>).
/// </remarks>
public static class SceneTessellator
{
  /// <summary>Tessellates <paramref name="scene"/> as it is now (set an animated scene's time first).</summary>
  /// <param name="scene">The scene; its camera's size is set to the options' image size, as the renderer sets it.</param>
  /// <param name="options">Segment counts and image size; null = <see cref="TessellationOptions.Default"/>.</param>
  public static SceneTessellation Tessellate(IRayScene scene, TessellationOptions? options = null)
  {
    ArgumentNullException.ThrowIfNull(scene);
    options ??= TessellationOptions.Default;
    var walk = new Walk(options);
    if (scene.Intersectable is ISceneNode root)
      walk.Root(root);
    else if (scene.Intersectable != null)
      walk.Notes.Add($"the scene's root is a {scene.Intersectable.GetType().Name}, not a scene node: nothing to show");

    TessellatedCamera? camera = scene.Camera != null ? CameraOf(scene.Camera, options, walk.Notes) : null;
    var lights = new List<TessellatedLight>();
    if (scene.Sources != null)
      foreach (ILightSource light in scene.Sources)
        if (LightOf(light, walk.Notes) is TessellatedLight l)
          lights.Add(l);

    // Unbounded solids are cut to the box of everything finite, the camera and the lights, grown on every side.
    Aabb bounds = walk.FiniteBounds;
    if (camera != null)
      bounds.Add(camera.Position);
    foreach (TessellatedLight l in lights)
      bounds.Add(l.Position);
    if (bounds.IsEmpty)
      bounds = new Aabb(new Vector3d(-1.0), new Vector3d(1.0));
    Vector3d grow = new(Math.Max((bounds.Max - bounds.Min).Length, 1.0));
    var around = new Aabb(bounds.Min - grow, bounds.Max + grow);

    return new SceneTessellation
    {
      Parts = walk.Finish(around),
      Lights = lights,
      Camera = camera,
      Notes = walk.Notes,
    };
  }

  /// <summary>The depth-first walk: collects finite parts at once and unbounded ones for when the scene's box is known.</summary>
  sealed class Walk(TessellationOptions options)
  {
    readonly List<Func<Aabb, TessellatedPart>> parts = new();
    // Equal shapes share their arrays (a sphere flake's thousands of unit spheres are one mesh in a glTF file).
    readonly Dictionary<string, (Vector3d[] Positions, int[] Indices, double Tolerance)> shapes = new();
    public readonly List<string> Notes = new();
    public Aabb FiniteBounds = Aabb.Empty;

    public void Root(ISceneNode root)
    {
      if (root.Children.Count > 0)
        Children(root, Matrix4d.Identity, OperationOf(root, null));
      else
        Leaf(root, Matrix4d.Identity, null);
    }

    void Children(ISceneNode node, in Matrix4d toWorld, SetOperation? operation)
    {
      foreach (ISceneNode child in node.Children)
      {
        // Row vectors: the child's world matrix is its ToParent followed by the parent's.
        Matrix4d world = child.ToParent * toWorld;
        if (child.Children.Count > 0)
          Children(child, world, OperationOf(child, operation));
        else
          Leaf(child, world, operation);
      }
    }

    /// <summary>A non-union library CSG node names the operation its leaves are operands of; a union keeps the one above.</summary>
    static SetOperation? OperationOf(ISceneNode node, SetOperation? above) =>
      node is CSGInnerNode csg && csg.Operation != SetOperation.Union ? csg.Operation : above;

    void Leaf(ISceneNode node, Matrix4d toWorld, SetOperation? operation)
    {
      int index = parts.Count + 1;
      Vector3d color = ColorOf(node);
      string name = $"{node.GetType().Name} {index.ToString(CultureInfo.InvariantCulture)}";

      TessellatedPart Shared(string key, Func<(TriangleBuilder, double)> make, PartKind kind = PartKind.Surface)
      {
        if (!shapes.TryGetValue(key, out var shape))
        {
          (TriangleBuilder b, double tolerance) = make();
          shapes[key] = shape = (b.Positions, b.Indices, tolerance);
        }
        return PartOf(shape.Positions, shape.Indices, kind, shape.Tolerance);
      }

      TessellatedPart Part(TriangleBuilder b, PartKind kind, double tolerance = 0.0, string? note = null) =>
        PartOf(b.Positions, b.Indices, kind, tolerance, note);

      TessellatedPart PartOf(Vector3d[] positions, int[] indices, PartKind kind, double tolerance = 0.0, string? note = null) => new()
      {
        Name = name,
        Node = node,
        Kind = kind,
        CsgOperation = operation,
        BaseColor = color,
        LocalToWorld = toWorld,
        Positions = positions,
        Indices = indices,
        Tolerance = tolerance,
        Note = note,
      };

      void Finite(TessellatedPart part)
      {
        for (int i = 0; i < part.Positions.Length; i++)
          FiniteBounds.Add(part.WorldPosition(i));
        parts.Add(_ => part);
      }

      switch (node)
      {
        case SphereFront s when SubclassCheck.KeepsGeometry(s, typeof(SphereFront)):
        case Sphere s2 when SubclassCheck.KeepsGeometry(s2, typeof(Sphere)):
          Finite(Shared("sphere", () => (SolidMeshes.Sphere(options.SphereSegments, options.SphereRings, out double st), st)));
          return;
        case Cube c when SubclassCheck.KeepsGeometry(c, typeof(Cube)):
          Finite(Shared("cube", () => (SolidMeshes.Cube(), 0.0)));
          return;
        case CylinderFront cf when SubclassCheck.KeepsGeometry(cf, typeof(CylinderFront)):
          Cylinder(cf, caps: false);
          return;
        case Cylinder cy when SubclassCheck.KeepsGeometry(cy, typeof(Cylinder)):
          Cylinder(cy, caps: true);
          return;
        case Torus t when SubclassCheck.KeepsGeometry(t, typeof(Torus)):
          Finite(Shared(FormattableString.Invariant($"torus {t.bigRadius} {t.smallRadius}"),
                        () => (SolidMeshes.Torus(t.bigRadius, t.smallRadius, options.TorusSegments, options.TorusTubeSegments, out double tt), tt)));
          return;
        case Plane p when SubclassCheck.KeepsGeometry(p, typeof(Plane)):
          Plane(p);
          return;
        case BezierSurface bs when SubclassCheck.KeepsGeometry(bs, typeof(BezierSurface)):
          Finite(Part(SolidMeshes.Bezier(bs, options.BezierSteps), PartKind.Surface,
                      note: $"{bs.Patches} patches, {options.BezierSteps}x{options.BezierSteps} steps each"));
          return;
        case TriangleMesh m when SubclassCheck.KeepsGeometry(m, typeof(TriangleMesh)):
          Finite(Part(SolidMeshes.Mesh(m.Mesh), PartKind.Surface));
          return;
        case ISolid solid:
          solid.GetBoundingBox(out Vector3d c1, out Vector3d c2);
          if (!IsFinite(c1) || !IsFinite(c2) || c1.X > c2.X || c1.Y > c2.Y || c1.Z > c2.Z)
          {
            Notes.Add($"{name}: its bounding box is not a finite box; not shown");
            return;
          }
          Finite(Part(SolidMeshes.Box(c1, c2), PartKind.BoundingBox, note: "a solid of the script's own class: its bounding box"));
          Notes.Add($"{name}: a solid of the script's own class, shown as its bounding box");
          return;
        default:
          Notes.Add($"{name}: not a solid and without children; not shown");
          return;
      }

      void Cylinder(Cylinder cy, bool caps)
      {
        if (double.IsFinite(cy.ZMin) && double.IsFinite(cy.ZMax))
        {
          Finite(Shared(FormattableString.Invariant($"cylinder {cy.ZMin} {cy.ZMax} {caps}"),
                        () => (SolidMeshes.Cylinder(cy.ZMin, cy.ZMax, caps, options.CylinderSegments, out double ct), ct)));
          return;
        }
        parts.Add(around =>
        {
          (Vector3d lo, Vector3d hi) = LocalRange(around, toWorld);
          double z0 = Math.Max(cy.ZMin, lo.Z), z1 = Math.Min(cy.ZMax, hi.Z);
          if (z1 <= z0)
            (z0, z1) = (lo.Z, hi.Z);
          bool closed = caps && double.IsFinite(cy.ZMin) && double.IsFinite(cy.ZMax);
          return Part(SolidMeshes.Cylinder(z0, z1, closed, options.CylinderSegments, out double ct), PartKind.Surface, ct,
                      "an unbounded cylinder, cut to the scene's bounds");
        });
      }

      void Plane(Plane p)
      {
        if (p.Triangle)
        {
          // x ≥ XMin, y ≥ YMin, x·XMax + y·YMax ≤ 1 (GrCis's triangle plane).
          var a = new Vector3d(p.XMin, p.YMin, 0.0);
          var b = new Vector3d((1.0 - p.YMin * p.YMax) / p.XMax, p.YMin, 0.0);
          var d = new Vector3d(p.XMin, (1.0 - p.XMin * p.XMax) / p.YMax, 0.0);
          if (IsFinite(b) && IsFinite(d))
          {
            Finite(Part(SolidMeshes.FlatTriangle(a, b, d), PartKind.Surface));
            return;
          }
        }
        if (double.IsFinite(p.XMin) && double.IsFinite(p.XMax) && double.IsFinite(p.YMin) && double.IsFinite(p.YMax))
        {
          Finite(Part(SolidMeshes.Rectangle(p.XMin, p.XMax, p.YMin, p.YMax), PartKind.Surface));
          return;
        }
        parts.Add(around =>
        {
          (Vector3d lo, Vector3d hi) = LocalRange(around, toWorld);
          double x0 = Math.Max(p.XMin, lo.X), x1 = Math.Min(p.XMax, hi.X);
          double y0 = Math.Max(p.YMin, lo.Y), y1 = Math.Min(p.YMax, hi.Y);
          if (x1 <= x0)
            (x0, x1) = (lo.X, hi.X);
          if (y1 <= y0)
            (y0, y1) = (lo.Y, hi.Y);
          return Part(SolidMeshes.Rectangle(x0, x1, y0, y1), PartKind.Surface, note: "an unbounded plane, cut to a patch around the scene");
        });
      }
    }

    /// <summary>The box <paramref name="around"/> (world) in a solid's local coordinates: the range of its corners.</summary>
    static (Vector3d Lo, Vector3d Hi) LocalRange(Aabb around, in Matrix4d toWorld)
    {
      Matrix4d toLocal = toWorld.Inverted();
      Vector3d lo = new(double.PositiveInfinity), hi = new(double.NegativeInfinity);
      for (int k = 0; k < 8; k++)
      {
        var corner = new Vector3d((k & 1) == 0 ? around.Min.X : around.Max.X, (k & 2) == 0 ? around.Min.Y : around.Max.Y,
                                  (k & 4) == 0 ? around.Min.Z : around.Max.Z);
        Vector3d local = Vector3d.TransformPosition(corner, toLocal);
        lo = Vector3d.ComponentMin(lo, local);
        hi = Vector3d.ComponentMax(hi, local);
      }
      return (lo, hi);
    }

    public List<TessellatedPart> Finish(Aabb around)
    {
      var result = new List<TessellatedPart>(parts.Count);
      foreach (Func<Aabb, TessellatedPart> make in parts)
        result.Add(make(around));
      return result;
    }
  }

  static bool IsFinite(Vector3d v) => double.IsFinite(v.X) && double.IsFinite(v.Y) && double.IsFinite(v.Z);

  /// <summary>The colour a hit on <paramref name="node"/> starts from: its COLOR attribute, else its material's colour (as <see cref="Intersection"/> completes it).</summary>
  static Vector3d ColorOf(ISceneNode node)
  {
    IReflectanceModel model = node.GetAttribute(PropertyName.REFLECTANCE_MODEL) as IReflectanceModel ?? new PhongModel();
    IMaterial material = node.GetAttribute(PropertyName.MATERIAL) as IMaterial ?? model.DefaultMaterial();
    double[]? color = node.GetAttribute(PropertyName.COLOR) as double[] ?? material.Color;
    return Rgb(color, 0.5);
  }

  /// <summary>The first three bands (one band: grey); <paramref name="fallback"/> grey for none.</summary>
  static Vector3d Rgb(double[]? bands, double fallback) => bands switch
  {
    null or { Length: 0 } => new Vector3d(fallback),
    { Length: 1 } => new Vector3d(bands[0]),
    { Length: 2 } => new Vector3d(bands[0], bands[1], bands[1]),
    _ => new Vector3d(bands[0], bands[1], bands[2]),
  };

  static TessellatedLight? LightOf(ILightSource light, List<string> notes)
  {
    double[]? bands = (light as PointLightSource)?.intensity;
    switch (light)
    {
      case RectangleLightSource r:
        return new TessellatedLight
        {
          Kind = TessellatedLightKind.Rectangle, Source = light, Intensity = Rgb(bands, 1.0),
          Position = (r.position ?? Vector3d.Zero) + 0.5 * (r.width + r.height), EdgeU = r.width, EdgeV = r.height,
        };
      case SphereLightSource s:
        return new TessellatedLight
        {
          Kind = TessellatedLightKind.Sphere, Source = light, Intensity = Rgb(bands, 1.0),
          Position = s.position ?? Vector3d.Zero, Radius = s.radius,
        };
      default:
        if (light.position is not Vector3d p)
        {
          if (light is not AmbientLightSource)
            notes.Add($"a {light.GetType().Name} without a position is not shown");
          return null;
        }
        return new TessellatedLight { Kind = TessellatedLightKind.Point, Source = light, Intensity = Rgb(bands, 1.0), Position = p };
    }
  }

  /// <summary>The camera after setting its image size; a <see cref="StaticCamera"/> read from its fields, any other measured from its rays.</summary>
  static TessellatedCamera? CameraOf(ICamera camera, TessellationOptions options, List<string> notes)
  {
    // Only when it differs: a scene on show (the studio's) was set to its render's size already, perhaps by a render running now.
    if (camera.Width != options.Width)
      camera.Width = options.Width;
    if (camera.Height != options.Height)
      camera.Height = options.Height;
    double aspect = options.Width / (double)options.Height;
    if (camera is StaticCamera s)
    {
      Vector3d dir = s.direction.Normalized();
      Vector3d left = Vector3d.Cross(dir, s.up).Normalized();
      Vector3d top = Vector3d.Cross(left, dir).Normalized();
      double halfHeight = Math.Tan(0.5 * s.hAngle) / aspect;
      return new TessellatedCamera
      {
        Position = s.center, Direction = dir, Up = top, VerticalFov = 2.0 * Math.Atan(halfHeight), AspectRatio = aspect, Exact = true,
      };
    }

    double cx = 0.5 * options.Width, cy = 0.5 * options.Height;
    if (!camera.GetRay(cx, cy, out Vector3d p0, out Vector3d d) || !camera.GetRay(cx, 0.0, out _, out Vector3d dTop) ||
        !camera.GetRay(cx, options.Height, out _, out Vector3d dBottom))
    {
      notes.Add($"the {camera.GetType().Name} gives no ray through the image centre or its edges: no camera");
      return null;
    }
    d = d.Normalized();
    Vector3d upv = dTop.Normalized() - d;
    upv = (upv - Vector3d.Dot(upv, d) * d).Normalized();
    double fov = Vector3d.CalculateAngle(dTop, d) + Vector3d.CalculateAngle(dBottom, d);
    notes.Add($"the {camera.GetType().Name} is the script's own camera: shown as the pinhole through its centre ray");
    return new TessellatedCamera { Position = p0, Direction = d, Up = upv, VerticalFov = fov, AspectRatio = aspect };
  }
}
