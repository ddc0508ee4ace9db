using System;
using System.Runtime.CompilerServices;
using Rendering.Imaging;

namespace Rendering.Accel;

/// <summary>
/// What each shortcut needs from the objects it meets, named once: every "is this the library's class, or a
/// subclass that changes nothing the shortcut relies on" decision of the renderer and of the front ends is a
/// predicate here, answered by <see cref="SubclassCheck"/> (reflection once per class, cached). The scene
/// preparation records its answers in the prepared scene's <see cref="SceneCapabilities"/>; the shading and the
/// front ends ask the rest once per function, renderer or render, and the per-hit shading only the inline
/// exact-type tests. The library's solids the prepared scene calls by name are in <c>LibraryTypes.Solids.cs</c>.
/// </summary>
internal static partial class LibraryTypes
{
  // ---------------------------------------------------------------- the scene graph (decided when a scene is prepared)

  /// <summary>A library union without a bounding volume: a pure container, whose members the prepared scene flattens.</summary>
  public static bool IsFlattenedUnion(ISceneNode node) =>
    SubclassCheck.OverridesNothing(node, typeof(CSGInnerNode)) &&
    node is CSGInnerNode c && c.Operation == SetOperation.Union && c.BoundingVolume == null;

  /// <summary>
  /// A library CSG node (any operation) without a bounding volume: the CSG kernel may evaluate it. A script's
  /// subclass or an <see cref="AnimatedCSGInnerNode"/> (it adds <see cref="ITimeDependent"/>) merges its own way.
  /// </summary>
  public static bool IsKernelCsg(ISceneNode node) =>
    SubclassCheck.OverridesNothing(node, typeof(CSGInnerNode)) && ((CSGInnerNode)node).BoundingVolume == null;

  /// <summary>A library CSG node: its records lie within the box combined from its children's (with its operation).</summary>
  public static bool CombinesChildBoxes(ISceneNode node) => SubclassCheck.OverridesNothing(node, typeof(CSGInnerNode));

  /// <summary>
  /// Hits shaded by the library's Phong model and material, which read only the world point, normal, colour
  /// and material of a hit (never its local frame): the condition of a surface-only completion.
  /// </summary>
  public static bool IsLibraryPhong(IReflectanceModel? model, IMaterial? material) =>
    SubclassCheck.OverridesNothing(model, typeof(PhongModel)) && SubclassCheck.OverridesNothing(material, typeof(PhongMaterial));

  /// <summary>A texture that reads only a hit's texture coordinate and surface colour (the library's checker and image textures).</summary>
  public static bool ReadsOnlyTextureCoord(ITexture texture) =>
    SubclassCheck.OverridesNothing(texture, typeof(CheckerTexture)) || SubclassCheck.OverridesNothing(texture, typeof(ImageTexture));

  // ---------------------------------------------------------------- shading

  /// <summary>
  /// The library's own scene classes (<see cref="DefaultRayScene"/>, <see cref="AnimatedRayScene"/>, exactly): their
  /// parts are plain properties, which the Whitted kernel reads once per frame (<see cref="BoundScene"/>). A script's
  /// own scene class is asked per ray.
  /// </summary>
  public static bool IsLibraryScene(IRayScene scene) =>
    scene.GetType() == typeof(DefaultRayScene) || scene.GetType() == typeof(AnimatedRayScene);

  /// <summary>The camera when it is exactly the library's <see cref="StaticCamera"/> (the kernel calls its ray directly), else null.</summary>
  public static StaticCamera? DirectCamera(ICamera? camera) =>
    camera != null && camera.GetType() == typeof(StaticCamera) ? (StaticCamera)camera : null;

  /// <summary>The background when it is exactly the library's <see cref="DefaultBackground"/>, else null.</summary>
  public static DefaultBackground? DirectBackground(IBackground? background) =>
    background != null && background.GetType() == typeof(DefaultBackground) ? (DefaultBackground)background : null;

  /// <summary>The library light the kernel may call directly: exactly a <see cref="PointLightSource"/> or an <see cref="AmbientLightSource"/>.</summary>
  public static DirectLight DirectLight(ILightSource light) =>
    light.GetType() == typeof(PointLightSource) ? Accel.DirectLight.Point :
    light.GetType() == typeof(AmbientLightSource) ? Accel.DirectLight.Ambient : Accel.DirectLight.None;


  /// <summary>A library light: it reads only the world point and normal of a hit.</summary>
  public static bool IsLibraryLight(ILightSource light) =>
    SubclassCheck.OverridesNothing(light, typeof(PointLightSource)) || SubclassCheck.OverridesNothing(light, typeof(AmbientLightSource)) ||
    SubclassCheck.OverridesNothing(light, typeof(RectangleLightSource)) || SubclassCheck.OverridesNothing(light, typeof(SphereLightSource));

  /// <summary>
  /// The library's ambient light (or a subclass overriding nothing): light without a direction, which the path tracer
  /// leaves out (its indirect light replaces it). A subclass with its own intensity is a light like any other.
  /// </summary>
  public static bool IsAmbientLight(ILightSource light) => SubclassCheck.OverridesNothing(light, typeof(AmbientLightSource));

  /// <summary>
  /// The library's Phong model (or a subclass overriding nothing): the shading may evaluate it for a
  /// <see cref="PhongMaterial"/> into stack buffers instead of a new array per light. Asked per hit (hits of list members carry no prepared decision): the exact
  /// type is answered inline.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool IsLibraryPhongModel(IReflectanceModel? model) => SubclassCheck.OverridesNothing(model, typeof(PhongModel));

  /// <summary>
  /// Exactly a <see cref="PhongMaterial"/>: its values may be copied into a pooled scratch material instead of a clone
  /// per hit. Exact, not "overrides nothing": the copy is a <see cref="PhongMaterial"/>, and a subclass's own type
  /// (and fields) must reach the lights and models that look at it.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool CopiesIntoScratch(IMaterial material) => material.GetType() == typeof(PhongMaterial);

  /// <summary>
  /// A member the Whitted kernel may shade without a hit object (its plain-surface path): exactly the library's
  /// <see cref="Sphere"/>, <see cref="Plane"/> or <see cref="Cube"/>, completed surface-only, shaded by the library's Phong
  /// model and exactly a <see cref="PhongMaterial"/> with no RECURSION function, textured by nothing but exact
  /// <see cref="CheckerTexture"/>s, every colour of 1 to 16 bands. Decided when the scene is prepared.
  /// </summary>
  public static bool IsPlainSurface(in PreparedMember m)
  {
    bool solid = m.Direct is DirectSolid.Sphere or DirectSolid.Plane || m.RecordSolid?.GetType() == typeof(Cube);
    if (m.Csg != null || !solid || !m.AttributesCached || m.Recursion != null ||
        m.Completion is not (HitCompletion.Sphere or HitCompletion.SphereTextured or HitCompletion.Plane or HitCompletion.Cube) ||
        !IsLibraryPhongModel(m.Model) || m.Material?.GetType() != typeof(PhongMaterial) ||
        !FitsBands(m.Material.Color) || m.Color != null && !FitsBands(m.Color))
      return false;
    if (m.Textures != null)
      foreach (ITexture t in m.Textures)
        if (t.GetType() != typeof(CheckerTexture) || !FitsBands(((CheckerTexture)t).Color2))
          return false;
    return true;
  }

  static bool FitsBands(double[]? color) => color is { Length: > 0 and <= 16 };

  /// <summary>
  /// A <see cref="RayTracing"/> class that keeps Whitted's secondary directions (<c>ReflectionDirection</c>,
  /// <c>RefractionDirection</c>): the kernel's plain-surface path, which has no hit object to pass them, may take its rays.
  /// </summary>
  public static bool KeepsWhittedDirections(RayTracing function) =>
    !SubclassCheck.OverridesAnyBelow(function.GetType(), typeof(RayTracing), WhittedDirections);

  static readonly string[] WhittedDirections = [nameof(RayTracing.ReflectionDirection), nameof(RayTracing.RefractionDirection)];

  // ---------------------------------------------------------------- image functions (decided once per function)

  /// <summary>An image function class overriding a method that sees hits (<see cref="RayCasting.HitReaders"/>): it may read anything of a hit.</summary>
  public static bool ReadsWholeHits(Type function) => SubclassCheck.OverridesAny(function, RayCasting.HitReaders);

  /// <summary>An image function class with its own first-hit query: every ray must go through it.</summary>
  public static bool OverridesFirstHit(Type function) => SubclassCheck.OverridesAny(function, FirstHitName);

  static readonly string[] FirstHitName = [RayCasting.FirstHitName];

  /// <summary>
  /// A <see cref="RayTracing"/> whose class (the library's or a script's) keeps Whitted's sampling, shading and
  /// shadow query (<c>GetSample</c>, <c>shade</c>, <c>Occluded</c>): the <see cref="WhittedKernel"/> may take its
  /// samples. It may change the secondary rays' directions, its first-hit query or the shadow transmittance: the
  /// kernel asks the function for those.
  /// </summary>
  public static bool ShadesAsWhitted(RayTracing function) =>
    !SubclassCheck.OverridesAnyBelow(function.GetType(), typeof(RayTracing), WhittedShading);

  static readonly string[] WhittedShading = [nameof(RayTracing.GetSample), RayTracing.ShadeName, RayTracing.OccludedName];

  /// <summary>
  /// Exactly the library's <see cref="RayTracing"/> or <see cref="RayCasting"/>: a new one with
  /// <see cref="RayCasting.CopySettingsFrom"/> is the same function (a subclass may hold settings of its own).
  /// </summary>
  public static bool IsCopyableRayCaster(IImageFunction function) =>
    function.GetType() == typeof(RayTracing) || function.GetType() == typeof(RayCasting);

  /// <summary>A class declared in this library, not in a script or a module (whose objects may hold anything).</summary>
  public static bool IsLibraryClass(object o) => o.GetType().Assembly == SubclassCheck.Library;

  // ---------------------------------------------------------------- renderers (decided once per renderer)

  /// <summary>A renderer class overriding <see cref="ImageSynthesizer.RenderPixel"/> (written against GrCis): its pixels are display colours.</summary>
  public static bool ReturnsDisplayPixels(Type synthesizer) =>
    SubclassCheck.OverridesMethod(synthesizer, typeof(ImageSynthesizer), nameof(ImageSynthesizer.RenderPixel), RenderPixelParameters);

  /// <summary>A renderer class overriding <see cref="ImageSynthesizer.RenderRectangle"/>: it renders its rectangles its own way.</summary>
  public static bool RendersOwnRectangles(Type synthesizer) =>
    SubclassCheck.OverridesMethod(synthesizer, typeof(ImageSynthesizer), nameof(ImageSynthesizer.RenderRectangle), RenderRectangleParameters);

  static readonly Type[] RenderPixelParameters = [typeof(int), typeof(int), typeof(double[])];
  static readonly Type[] RenderRectangleParameters = [typeof(FloatImage), typeof(int), typeof(int), typeof(int), typeof(int)];

  /// <summary>
  /// Exactly the library's n×n grid with more than one sample: its samples may be taken in passes over the image
  /// that together give the image of one pass. A subclass (adaptive, a
  /// student's) renders its own way.
  /// </summary>
  public static bool TakesSamplesInPasses(ImageSynthesizer renderer) =>
    renderer.GetType() == typeof(SupersamplingImageSynthesizer) && ((SupersamplingImageSynthesizer)renderer).SuperXY > 1;
}
