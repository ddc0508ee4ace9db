using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using Matrix4d = OpenTK.Mathematics.Matrix4d;
using Vector3d = OpenTK.Mathematics.Vector3d;
using Rendering.Tessellation;
using SharpGLTF.Schema2;

namespace GrCis.Hosting.Export;

/// <summary>
/// Writes a <see cref="SceneTessellation"/> as glTF 2.0 with SharpGLTF: a node per part (its name, its transform, a mesh
/// with a base-colour PBR material), the camera as a perspective camera node, the lights as KHR_lights_punctual point
/// lights.
/// </summary>
/// <remarks>
/// GrCis's world is left-handed as cameras see it (a camera looking along +z has +x on its right); glTF's is
/// right-handed. The writer mirrors z (glTF z = −GrCis z) and reverses each triangle's corners, so a viewer sees the
/// render's picture, not its mirror image, and front faces stay outside. A part whose matrix is not a rotation, scale
/// and translation (glTF allows only those) gets its vertices in world coordinates and an identity node.
/// </remarks>
public static class GltfWriter
{
  /// <summary>The format the file name's extension asks for, or null for any other extension.</summary>
  public static GltfFormat? FormatOf(string path) => Path.GetExtension(path).ToLowerInvariant() switch
  {
    ".glb" => GltfFormat.Binary,
    ".gltf" => GltfFormat.Json,
    _ => null,
  };

  /// <summary>The glTF model of <paramref name="scene"/>; <paramref name="name"/> names its scene.</summary>
  public static ModelRoot ToModel(SceneTessellation scene, string name)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ModelRoot model = ModelRoot.CreateModel();
    Scene root = model.UseScene(name);
    var materials = new Dictionary<Vector3d, Material>();
    // Parts that share their vertex arrays (equal shapes) and colour share one glTF mesh.
    var meshes = new Dictionary<(Vector3d[], Material), Mesh>();
    var buffers = new Dictionary<Vector3d[], (Accessor Vertices, Accessor Indices)>();

    foreach (TessellatedPart part in scene.Parts)
    {
      if (part.TriangleCount == 0)
        continue;
      Node node = root.CreateNode(part.Name);
      Matrix4x4 local = Mirrored(part.LocalToWorld);
      bool asNode = IsTrs(local);
      Material material = MaterialOf(model, materials, part.BaseColor);
      if (!asNode)
        node.Mesh = MeshOf(model, part.Name, Accessors(model, part, part.LocalToWorld), material);
      else if (!meshes.TryGetValue((part.Positions, material), out Mesh? shared))
      {
        if (!buffers.TryGetValue(part.Positions, out var accessors))
          buffers[part.Positions] = accessors = Accessors(model, part, null);
        node.Mesh = meshes[(part.Positions, material)] = MeshOf(model, part.TypeName, accessors, material);
      }
      else
        node.Mesh = shared;
      if (asNode)
        node.LocalMatrix = local;
      node.Extras = Extras(part);
    }

    if (scene.Camera is TessellatedCamera cam)
    {
      Node node = root.CreateNode("Camera");
      Camera camera = model.CreateCamera("Camera");
      // glTF's far plane is optional (infinite); the near plane must be positive.
      camera.SetPerspectiveMode((float)cam.AspectRatio, (float)cam.VerticalFov, 0.01f, float.PositiveInfinity);
      node.Camera = camera;
      node.LocalMatrix = CameraMatrix(cam);
    }

    int index = 0;
    foreach (TessellatedLight light in scene.Lights)
    {
      index++;
      string lightName = $"{light.Kind} light {index}";
      PunctualLight punctual = model.CreatePunctualLight(lightName, PunctualLightType.Point);
      double max = Math.Max(light.Intensity.X, Math.Max(light.Intensity.Y, light.Intensity.Z));
      Vector3 color = max > 0.0 ? ToFloat(light.Intensity / max) : Vector3.One;
      // No range: GrCis lights reach everywhere.
      punctual.SetColor(color, (float)Math.Max(max, 0.0), float.PositiveInfinity);
      Node node = root.CreateNode(lightName);
      node.PunctualLight = punctual;
      node.LocalMatrix = Matrix4x4.CreateTranslation(ToFloat(Mirror(light.Position)));
    }
    return model;
  }

  /// <summary>The scene as a <c>.glb</c> file's bytes.</summary>
  public static byte[] ToGlb(SceneTessellation scene, string name)
  {
    using var stream = new MemoryStream();
    ToModel(scene, name).WriteGLB(stream);
    return stream.ToArray();
  }

  /// <summary>
  /// Writes <paramref name="path"/> (and, for <c>.gltf</c>, its <c>.bin</c> beside it) through temporary files and
  /// renames: a failed write leaves no file behind and an existing one as it was.
  /// </summary>
  /// <exception cref="ArgumentException">The extension is neither .glb nor .gltf.</exception>
  /// <exception cref="IOException">The file could not be written.</exception>
  /// <exception cref="UnauthorizedAccessException">The file could not be written.</exception>
  public static void Save(SceneTessellation scene, string path, string name)
  {
    GltfFormat format = FormatOf(path) ?? throw new ArgumentException($"'{path}': a glTF file ends in .glb or .gltf", nameof(path));
    string full = Path.GetFullPath(path);
    string dir = Path.GetDirectoryName(full)!;
    Directory.CreateDirectory(dir);
    ModelRoot model = ToModel(scene, name);
    if (format == GltfFormat.Binary)
    {
      Replace(full, temp => model.SaveGLB(temp));
      return;
    }

    // SharpGLTF names the buffer after the .gltf file: write both into a private folder, then move the .bin first.
    string stage = Path.Combine(dir, "." + Path.GetFileName(full) + ".tmp-" + Guid.NewGuid().ToString("N")[..12]);
    Directory.CreateDirectory(stage);
    try
    {
      string staged = Path.Combine(stage, Path.GetFileName(full));
      model.SaveGLTF(staged);
      foreach (string file in Directory.GetFiles(stage))
        if (!string.Equals(file, staged, StringComparison.Ordinal))
          File.Move(file, Path.Combine(dir, Path.GetFileName(file)), overwrite: true);
      File.Move(staged, full, overwrite: true);
    }
    finally
    {
      Directory.Delete(stage, recursive: true);
    }
  }

  static void Replace(string full, Action<string> write)
  {
    string temp = Path.Combine(Path.GetDirectoryName(full)!, "." + Path.GetFileName(full) + ".tmp-" + Guid.NewGuid().ToString("N")[..12] + Path.GetExtension(full));
    try
    {
      write(temp);
      File.Move(temp, full, overwrite: true);
    }
    finally
    {
      if (File.Exists(temp))
        File.Delete(temp);
    }
  }

  static Mesh MeshOf(ModelRoot model, string name, (Accessor Vertices, Accessor Indices) accessors, Material material)
  {
    Mesh mesh = model.CreateMesh(name);
    MeshPrimitive primitive = mesh.CreatePrimitive();
    primitive.SetVertexAccessor("POSITION", accessors.Vertices);
    primitive.SetIndexAccessor(accessors.Indices);
    primitive.DrawPrimitiveType = PrimitiveType.TRIANGLES;
    primitive.Material = material;
    return mesh;
  }

  /// <summary>The part's vertices (z mirrored; in world coordinates when <paramref name="bake"/> is given) and triangles.</summary>
  static (Accessor Vertices, Accessor Indices) Accessors(ModelRoot model, TessellatedPart part, Matrix4d? bake)
  {
    var positions = new Vector3[part.Positions.Length];
    for (int i = 0; i < positions.Length; i++)
    {
      Vector3d p = bake is Matrix4d m ? Vector3d.TransformPosition(part.Positions[i], m) : part.Positions[i];
      positions[i] = ToFloat(Mirror(p));
    }
    // Mirroring turns every triangle over: swap two corners to keep the outside in front.
    int[] source = part.Indices;
    var indices = new uint[source.Length];
    for (int t = 0; t < source.Length; t += 3)
    {
      indices[t] = (uint)source[t];
      indices[t + 1] = (uint)source[t + 2];
      indices[t + 2] = (uint)source[t + 1];
    }

    byte[] vertexBytes = new byte[positions.Length * 12];
    System.Runtime.InteropServices.MemoryMarshal.AsBytes(positions.AsSpan()).CopyTo(vertexBytes);
    byte[] indexBytes = new byte[indices.Length * 4];
    System.Runtime.InteropServices.MemoryMarshal.AsBytes(indices.AsSpan()).CopyTo(indexBytes);

    BufferView vertexView = model.UseBufferView(vertexBytes, 0, null, 0, BufferMode.ARRAY_BUFFER);
    Accessor vertexAccessor = model.CreateAccessor();
    vertexAccessor.SetVertexData(vertexView, 0, positions.Length, new SharpGLTF.Memory.AttributeFormat(DimensionType.VEC3));
    BufferView indexView = model.UseBufferView(indexBytes, 0, null, 0, BufferMode.ELEMENT_ARRAY_BUFFER);
    Accessor indexAccessor = model.CreateAccessor();
    indexAccessor.SetIndexData(indexView, 0, indices.Length, IndexEncodingType.UNSIGNED_INT);
    return (vertexAccessor, indexAccessor);
  }

  static Material MaterialOf(ModelRoot model, Dictionary<Vector3d, Material> materials, Vector3d color)
  {
    if (materials.TryGetValue(color, out Material? known))
      return known;
    Material material = model.CreateMaterial($"Colour {materials.Count + 1}");
    material.InitializePBRMetallicRoughness();
    // Diffuse surfaces: GrCis's Phong colour as the base colour, no metal, fully rough; visible from both sides as rays see them.
    MaterialChannel baseColor = material.FindChannel("BaseColor")!.Value;
    baseColor.Color = new Vector4(ToFloat(Clamp01(color)), 1.0f);
    material.FindChannel("MetallicRoughness")!.Value.SetFactor("MetallicFactor", 0.0f);
    material.DoubleSided = true;
    materials.Add(color, material);
    return material;
  }

  static Vector3d Clamp01(Vector3d c) => new(Math.Clamp(c.X, 0.0, 1.0), Math.Clamp(c.Y, 0.0, 1.0), Math.Clamp(c.Z, 0.0, 1.0));

  static Dictionary<string, object> ExtrasFields(TessellatedPart part)
  {
    var extras = new Dictionary<string, object> { ["grcisType"] = part.TypeName, ["grcisKind"] = part.Kind.ToString() };
    if (part.CsgOperation is Rendering.SetOperation op)
      extras["grcisCsgOperation"] = op.ToString();
    if (part.Note != null)
      extras["grcisNote"] = part.Note;
    return extras;
  }

  static System.Text.Json.Nodes.JsonNode? Extras(TessellatedPart part) =>
    System.Text.Json.JsonSerializer.SerializeToNode(ExtrasFields(part));

  /// <summary>A row-vector GrCis matrix with z mirrored on both sides (S·M·S), as System.Numerics' row-vector matrix.</summary>
  static Matrix4x4 Mirrored(Matrix4d m)
  {
    var r = new Matrix4x4(
      (float)m.M11, (float)m.M12, (float)m.M13, (float)m.M14,
      (float)m.M21, (float)m.M22, (float)m.M23, (float)m.M24,
      (float)m.M31, (float)m.M32, (float)m.M33, (float)m.M34,
      (float)m.M41, (float)m.M42, (float)m.M43, (float)m.M44);
    r.M13 = -r.M13; r.M23 = -r.M23; r.M43 = -r.M43;
    r.M31 = -r.M31; r.M32 = -r.M32; r.M34 = -r.M34;
    return r;
  }

  /// <summary>Whether glTF can hold <paramref name="m"/> as a node matrix: affine, and a translation, rotation and scale exactly (no shear).</summary>
  static bool IsTrs(Matrix4x4 m)
  {
    if (m.M14 != 0f || m.M24 != 0f || m.M34 != 0f || m.M44 != 1f)
      return false;
    if (!Matrix4x4.Decompose(m, out Vector3 scale, out Quaternion rotation, out Vector3 translation) || scale.X * scale.Y * scale.Z == 0f)
      return false;
    // Composed again, it must give the same entries within an absolute 1e-5, as strict as glTF validators are (the
    // Khronos validator allows 5e-5): a long thin ellipsoid (scale 900 beside 0.9) fails that in single precision and
    // goes into the vertices.
    Matrix4x4 back = Matrix4x4.CreateScale(scale) * Matrix4x4.CreateFromQuaternion(rotation) * Matrix4x4.CreateTranslation(translation);
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
        if (Math.Abs(back[i, j] - m[i, j]) > 1e-5f)
          return false;
    return true;
  }

  /// <summary>The camera node: glTF cameras look along their −z with +y up and +x to the right.</summary>
  static Matrix4x4 CameraMatrix(TessellatedCamera cam)
  {
    Vector3 forward = Vector3.Normalize(ToFloat(Mirror(cam.Direction)));
    Vector3 up = Vector3.Normalize(ToFloat(Mirror(cam.Up)));
    Vector3 right = Vector3.Normalize(Vector3.Cross(forward, up));
    up = Vector3.Cross(right, forward);
    Vector3 position = ToFloat(Mirror(cam.Position));
    // Rows are the images of the local axes (row vectors): x → right, y → up, z → −forward.
    return new Matrix4x4(
      right.X, right.Y, right.Z, 0f,
      up.X, up.Y, up.Z, 0f,
      -forward.X, -forward.Y, -forward.Z, 0f,
      position.X, position.Y, position.Z, 1f);
  }

  /// <summary>GrCis world → glTF world: z mirrored.</summary>
  public static Vector3d Mirror(Vector3d v) => new(v.X, v.Y, -v.Z);

  static Vector3 ToFloat(Vector3d v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
