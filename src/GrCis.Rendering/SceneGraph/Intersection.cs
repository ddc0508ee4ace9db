using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// One ray–solid hit. The solid fills the cheap part (T, Enter, Front, local coordinates);
/// <see cref="Complete"/> fills the rest only for the hit that is actually shaded.
/// </summary>
public class Intersection : IComparable<Intersection>
{
  /// <summary>Thickness of thin shells (one-sided solids).</summary>
  public const double SHELL_THICKNESS = 1.0e-5;

  /// <summary>Minimal distance of a secondary hit from the ray origin.</summary>
  public const double RAY_EPSILON = 1.0e-4;

  /// <summary>Square of <see cref="RAY_EPSILON"/>: hits are accepted when <c>T² · |p1|² &gt; RAY_EPSILON2</c>.</summary>
  public const double RAY_EPSILON2 = RAY_EPSILON * RAY_EPSILON;

  /// <summary>The ray enters the solid's interior here.</summary>
  public bool Enter;

  /// <summary>The ray hits the surface from its front (against the local normal).</summary>
  public bool Front;

  /// <summary>Ray parameter of the hit.</summary>
  public double T;

  /// <summary>The solid that was hit; its attributes give the material, colour and textures at completion.</summary>
  public ISolid? Solid;

  /// <summary>Anything the solid wants to remember until completion.</summary>
  public object? SolidData;

  /// <summary>The hit point in the solid's local coordinates (set by the solid when it lists the hit).</summary>
  public Vector3d CoordLocal;
  /// <summary>Surface normal in local coordinates, not necessarily of unit length (the solid sets it, at listing or at completion).</summary>
  public Vector3d NormalLocal;

  // Filled by Complete().
  /// <summary>The hit point in world coordinates (set by completion).</summary>
  public Vector3d CoordWorld;
  /// <summary>The hit point in object coordinates (<see cref="ISceneNode.ToObject"/>; set by completion), for solid textures.</summary>
  public Vector3d CoordObject;
  /// <summary>Surface texture coordinates (u, v), set by the solid's <see cref="IIntersectable.CompleteIntersection"/>; the range depends on the solid (see its class).</summary>
  public Vector2d TextureCoord;
  /// <summary>
  /// Unit surface normal in world space (set by completion): the solid's normal, turned round where
  /// <see cref="Enter"/> and <see cref="Front"/> differ (a CSG operation changed Enter), so that it points out of the resulting solid.
  /// </summary>
  public Vector3d Normal;
  /// <summary>
  /// Surface tangent along growing u. The library's solids set it in world space, of unit length; when a solid
  /// leaves it zero, completion puts in a local-space tangent of <see cref="NormalLocal"/>.
  /// </summary>
  public Vector3d TangentU;
  /// <summary>Surface tangent along growing v; set like <see cref="TangentU"/>.</summary>
  public Vector3d TangentV;
  /// <summary>The solid's local → world transform (set by completion).</summary>
  public Matrix4d LocalToWorld;
  /// <summary>The world → local transform, the inverse of <see cref="LocalToWorld"/> (set by completion).</summary>
  public Matrix4d WorldToLocal;
  /// <summary>The solid's local → object transform (<see cref="ISceneNode.ToObject"/>; set by completion).</summary>
  public Matrix4d LocalToObject;
  /// <summary>
  /// Colour of the surface at the hit, one value per band: after completion a copy of the solid's <see cref="PropertyName.COLOR"/>
  /// attribute, else of its material's colour, else black. Textures change it.
  /// </summary>
  public double[]? SurfaceColor;
  /// <summary>The solid's <see cref="PropertyName.REFLECTANCE_MODEL"/> attribute, or a new <see cref="PhongModel"/> when it has none (set by completion).</summary>
  public IReflectanceModel? ReflectanceModel;
  /// <summary>The solid's <see cref="PropertyName.MATERIAL"/> attribute, or the reflectance model's default material (set by completion).</summary>
  public IMaterial? Material;
  /// <summary>Textures that apply to the hit, the outermost node's first (<see cref="ISceneNode.GetTextures"/>; set by completion), or null.</summary>
  public LinkedList<ITexture>? Textures;

  /// <summary>True once <see cref="Complete"/> (or another completion) has filled the fields; a second completion does nothing.</summary>
  public bool completed;
  /// <summary>Set true by the library's textures (<see cref="CheckerTexture"/>, <see cref="ImageTexture"/>) when they are applied to the hit.</summary>
  public bool textureApplied;

  /// <summary>An empty hit with no solid.</summary>
  public Intersection() { }

  /// <summary>A hit on solid <paramref name="s"/>; the solid then sets <see cref="T"/>, <see cref="Enter"/>, <see cref="Front"/> and the local coordinates.</summary>
  /// <param name="s">The solid that was hit.</param>
  public Intersection(ISolid? s) => Solid = s;

  /// <summary>Copy of the cheap (pre-completion) part; used when CSG changes Enter.</summary>
  public Intersection(Intersection i)
  {
    Enter = i.Enter;
    Front = i.Front;
    T = i.T;
    Solid = i.Solid;
    SolidData = i.SolidData;
    CoordLocal = i.CoordLocal;
    NormalLocal = i.NormalLocal;
  }

  /// <summary>Orders hits by the ray parameter <see cref="T"/>; any hit comes after null.</summary>
  public int CompareTo(Intersection? other) => other == null ? 1 : T.CompareTo(other.T);

  /// <summary>
  /// Computes world coordinates, normal (see <see cref="Normal"/>), material,
  /// surface colour and textures, resolving attributes up the scene hierarchy.
  /// </summary>
  public void Complete()
  {
    if (completed)
      return;
    if (Solid != null)
    {
      LocalToWorld = Solid.ToWorld();
      WorldToLocal = LocalToWorld.Inverted();
      LocalToObject = Solid.ToObject();
      CompleteWith(LocalToWorld, WorldToLocal, LocalToObject);
      return;
    }
    BlackIfUncoloured();
    completed = true;
  }

  /// <summary>Completion with transforms that the caller already knows (the prepared fast path).</summary>
  public void CompleteWith(in Matrix4d localToWorld, in Matrix4d worldToLocal, in Matrix4d localToObject)
  {
    if (completed)
      return;
    LocalToWorld = localToWorld;
    WorldToLocal = worldToLocal;
    LocalToObject = localToObject;
    if (Solid != null)
    {
      CoordWorld = Vector3d.TransformPosition(CoordLocal, LocalToWorld);
      CoordObject = Vector3d.TransformPosition(CoordLocal, LocalToObject);

      ReflectanceModel = Solid.GetAttribute(PropertyName.REFLECTANCE_MODEL) as IReflectanceModel ?? new PhongModel();
      Material = Solid.GetAttribute(PropertyName.MATERIAL) as IMaterial ?? ReflectanceModel.DefaultMaterial();
      if (SurfaceColor == null)
      {
        double[]? color = Solid.GetAttribute(PropertyName.COLOR) as double[] ?? Material.Color;
        SurfaceColor = color != null ? (double[])color.Clone() : null;
      }
      Textures = Solid.GetTextures();

      Solid.CompleteIntersection(this);
      CompleteFrame();
      Normal.Normalize();
      if (Enter != Front)
        Normal = -Normal;
    }
    BlackIfUncoloured();
    completed = true;
  }

  /// <summary>
  /// GrCis's completion contract (since May 2020) for what the solid's <c>CompleteIntersection</c> left zero:
  /// no tangents — GrCis's tangents of <see cref="NormalLocal"/>; tangents but no local normal — their cross
  /// product; no world normal — the cross product of the tangents carried to world space (the normal transform,
  /// right under non-uniform scale too). A student's solid may fill only <see cref="NormalLocal"/> or only the
  /// local tangents. The library's solids fill all three, so for them this changes nothing.
  /// </summary>
  void CompleteFrame()
  {
    if (IsZeroLength(TangentU))
      MathSupport.Geometry.GetTangents(ref NormalLocal, out TangentU, out TangentV);
    else if (IsZeroLength(NormalLocal))
      NormalLocal = Vector3d.Cross(TangentU, TangentV);

    if (IsZeroLength(Normal))
      Normal = Vector3d.Cross(Vector3d.TransformVector(TangentU, LocalToWorld), Vector3d.TransformVector(TangentV, LocalToWorld));
  }

  /// <summary>GrCis's test of a vector left unset: length at most 1e-12.</summary>
  static bool IsZeroLength(in Vector3d v) => v.LengthSquared <= 1.0e-24;

  /// <summary>The solid's RECURSION attribute resolved at prepare time (valid when <see cref="RecursionCached"/>).</summary>
  internal object? CachedRecursion;
  internal bool RecursionCached;

  /// <summary>The solid's <see cref="PropertyName.RECURSION"/> attribute (from the prepared scene when it resolved it).</summary>
  internal object? RecursionAttribute => RecursionCached ? CachedRecursion : Solid?.GetAttribute(PropertyName.RECURSION);

  // This object's own surface-colour copy, reused when the object is (pooled fast path).
  double[]? spareColor;

  /// <summary>
  /// Sets the surface colour to a copy of <paramref name="color"/> by overwriting this hit's own pooled
  /// copy when it holds the current colour (same values as a fresh clone, no allocation); false otherwise.
  /// </summary>
  internal bool TryCopySurfaceColor(ReadOnlySpan<double> color)
  {
    double[]? own = spareColor;
    if (own == null || !ReferenceEquals(SurfaceColor, own) || own.Length != color.Length)
      return false;
    color.CopyTo(own);
    return true;
  }

  /// <summary>
  /// Makes a pooled intersection fresh for <paramref name="solid"/>: every field as after
  /// <c>new Intersection(solid)</c> except the three matrices, which completion always sets (the fast
  /// path reuses one object per thread and recursion depth).
  /// </summary>
  internal void Reset(ISolid solid)
  {
    Enter = Front = false;
    T = 0.0;
    Solid = solid;
    SolidData = null;
    CoordLocal = NormalLocal = CoordWorld = CoordObject = Normal = TangentU = TangentV = default;
    TextureCoord = default;
    // LocalToWorld, WorldToLocal and LocalToObject (384 bytes) are not cleared: the prepared scene's
    // CompleteCached/CompleteWith overwrites all three before the hit is handed out.
    SurfaceColor = null;
    ReflectanceModel = null;
    Material = null;
    Textures = null;
    CachedRecursion = null;
    RecursionCached = false;
    completed = textureApplied = false;
  }

  /// <summary>
  /// <see cref="CompleteWith"/> with the solid's attributes resolved at prepare time (the same look-ups,
  /// done once per prepared member instead of once per hit): reflectance model, material, colour, textures.
  /// </summary>
  internal void CompleteCached(in Matrix4d localToWorld, in Matrix4d worldToLocal, in Matrix4d localToObject,
                               IReflectanceModel model, IMaterial material, double[]? color, LinkedList<ITexture>? textures,
                               object? recursion)
  {
    CachedRecursion = recursion;
    RecursionCached = true;
    if (completed)
      return;
    LocalToWorld = localToWorld;
    WorldToLocal = worldToLocal;
    LocalToObject = localToObject;
    CoordWorld = Vector3d.TransformPosition(CoordLocal, LocalToWorld);
    CoordObject = Vector3d.TransformPosition(CoordLocal, LocalToObject);
    ReflectanceModel = model;
    Material = material;
    CopyCachedColor(color);
    Textures = textures;

    Solid!.CompleteIntersection(this);
    CompleteFrame();
    Normal.Normalize();
    if (Enter != Front)
      Normal = -Normal;
    BlackIfUncoloured();
    completed = true;
  }

  void CopyCachedColor(double[]? color)
  {
    if (SurfaceColor == null && color != null)
    {
      // GrCis copies the colour per hit (textures may change it): reuse this object's own copy.
      double[] own = Spare(color.Length);
      // A loop: Array.Copy's call and GC poll cost more than three doubles.
      for (int k = 0; k < own.Length; k++)
        own[k] = color[k];
      SurfaceColor = own;
    }
  }

  /// <summary>
  /// A hit with no colour gets black, an array of its own (GrCis's fresh { 0, 0, 0 }); a pooled object reuses its
  /// spare array for it, so an uncoloured solid costs no allocation per hit either.
  /// </summary>
  void BlackIfUncoloured()
  {
    if (SurfaceColor != null)
      return;
    double[] own = Spare(3);
    Array.Clear(own);
    SurfaceColor = own;
  }

  /// <summary>This object's own colour array of <paramref name="length"/> bands, made once and reused by the hits it holds.</summary>
  double[] Spare(int length)
  {
    if (spareColor == null || spareColor.Length != length)
      spareColor = new double[length];
    return spareColor;
  }

  /// <summary>The part of a fast-path record every solid lists the same way (T, Enter, Front, local coordinates).</summary>
  internal void SetRecord(in Accel.SolidRecord hit)
  {
    T = hit.T;
    Enter = hit.Enter;
    Front = hit.Front;
    CoordLocal = hit.CoordLocal;
  }

  /// <summary>
  /// The start of <see cref="CompleteCached"/> for a hit only the library's own shading reads (see <see cref="Accel.HitCompletion"/>):
  /// the world point and the attributes. The solid then sets the normal and, when a checker or image texture reads them, the
  /// texture coordinates, as its full completion computes them (tangents, object coordinates and the three matrices are left
  /// as they are), and <see cref="EndSurface"/> finishes. False when this hit is already complete.
  /// </summary>
  internal bool BeginSurface(in Matrix4d localToWorld, IReflectanceModel model, IMaterial material, double[]? color,
                             LinkedList<ITexture>? textures, object? recursion)
  {
    CachedRecursion = recursion;
    RecursionCached = true;
    if (completed)
      return false;
    CoordWorld = Vector3d.TransformPosition(CoordLocal, localToWorld);
    ReflectanceModel = model;
    Material = material;
    CopyCachedColor(color);
    Textures = textures;
    return true;
  }

  /// <summary>The end of a surface-only completion (<see cref="BeginSurface"/>): the normal unit length and facing the ray.</summary>
  internal void EndSurface()
  {
    Normal.Normalize();
    if (Enter != Front)
      Normal = -Normal;
    BlackIfUncoloured();
    completed = true;
  }

  /// <summary>The first hit in front of the ray origin (farther than <see cref="RAY_EPSILON"/>), or null.</summary>
  public static Intersection? FirstIntersection(LinkedList<Intersection>? list, ref Vector3d p1)
  {
    if (list == null)
      return null;
    double len2 = p1.LengthSquared;
    foreach (Intersection i in list)
      if (i.T > 0.0 && i.T * i.T * len2 > RAY_EPSILON2)
        return i;
    return null;
  }

  /// <summary>Like <see cref="FirstIntersection"/> but skips solids marked <see cref="PropertyName.NO_SHADOW"/> (shadow rays).</summary>
  public static Intersection? FirstRealIntersection(LinkedList<Intersection>? list, ref Vector3d p1)
  {
    if (list == null)
      return null;
    double len2 = p1.LengthSquared;
    foreach (Intersection i in list)
      if (i.T > 0.0 && i.T * i.T * len2 > RAY_EPSILON2 &&
          (i.Solid == null || i.Solid.GetLocalAttribute(PropertyName.NO_SHADOW) == null))
        return i;
    return null;
  }

  /// <summary>True when this hit lies beyond ray parameter <paramref name="t"/> by more than the epsilon.</summary>
  public bool Far(double t, ref Vector3d p1)
  {
    if (T <= t)
      return false;
    double d = T - t;
    return d * d * p1.LengthSquared > RAY_EPSILON2;
  }

  /// <summary>Rays cast by finished renders (statistics): workers count per thread (<see cref="Execution.RayCounter"/>) and each render adds its total here when it ends.</summary>
  public static long countRays;

  /// <summary>Rays of finished renders that hit something (statistics; a blocked shadow ray counts), added per render as <see cref="countRays"/>.</summary>
  public static long countIntersections;
}
