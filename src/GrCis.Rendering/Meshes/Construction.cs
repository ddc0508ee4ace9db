using System;
using MathSupport;
using OpenTK.Mathematics;

namespace Scene3D;

/// <summary>
/// GrCis's mesh-construction homework template: <see cref="AddMesh"/> adds a shape to a <see cref="SceneBrep"/>.
/// Out of the box it is a regular tetrahedron with normals, texture coordinates and colours; students
/// replace the class with their own construction.
/// </summary>
public class Construction
{
  /// <summary>Default parameter text and author name shown by the hosting program.</summary>
  public static void InitParams(out string param, out string name)
  {
    param = "";
    name = "Josef Pelikán";
  }

  /// <summary>A construction with nothing to set up (a student's version may prepare its data here).</summary>
  public Construction()
  {
  }

  /// <summary>Adds the shape, transformed by <paramref name="m"/> (object to world space); returns the number of faces added.</summary>
  public int AddMesh(SceneBrep scene, Matrix4 m, string param)
  {
    scene.Reserve(4);
    return CreateTetrahedron(scene, m, 1.0f);
  }

  /// <summary>A regular tetrahedron centred at the origin, vertices <paramref name="size"/> from the z axis.</summary>
  static int CreateTetrahedron(SceneBrep scene, Matrix4 m, float size)
  {
    float z = size * MathF.Sqrt(0.5f);
    ReadOnlySpan<Vector3> corners = stackalloc Vector3[]
    {
      new(size, 0.0f, -z), new(-size, 0.0f, -z), new(0.0f, size, z), new(0.0f, -size, z),
    };
    ReadOnlySpan<Vector2> uv = stackalloc Vector2[] { new(1.0f, 0.0f), new(0.0f, 0.0f), new(1.0f, 1.0f), new(0.0f, 1.0f) };

    // A colour per placement: the translation seeds the generator, so copies in different places differ.
    ulong seed = (ulong)Math.Min(ulong.MaxValue, m.Row3.LengthSquared * 10000.0f);
    Span<float> color = stackalloc float[3];
    for (int i = 0; i < 3; i++)
    {
      seed = RandomStatic.numericRecipes(seed);
      color[i] = (seed & 255) / 255.0f;
    }

    Span<int> v = stackalloc int[4];
    for (int i = 0; i < 4; i++)
    {
      v[i] = scene.AddVertex(Vector3.TransformPosition(corners[i], m));
      // The centre is the origin, so a corner's position is also its normal.
      scene.SetNormal(v[i], Vector3.TransformVector(corners[i], m).Normalized());
      scene.SetTxtCoord(v[i], uv[i]);
      // Each later vertex is a little lighter in one more channel.
      if (i > 0)
        color[i - 1] = Math.Min(color[i - 1] + 0.2f, 1.0f);
      scene.SetColor(v[i], new Vector3(color[0], color[1], color[2]));
    }

    scene.AddTriangle(v[0], v[1], v[2]);
    scene.AddTriangle(v[2], v[1], v[3]);
    scene.AddTriangle(v[1], v[0], v[3]);
    scene.AddTriangle(v[2], v[3], v[0]);
    return 4;
  }
}
