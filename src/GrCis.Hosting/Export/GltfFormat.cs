namespace GrCis.Hosting.Export;

/// <summary>The two glTF 2.0 containers.</summary>
public enum GltfFormat
{
  /// <summary><c>.glb</c>: one binary file (JSON and buffer).</summary>
  Binary,

  /// <summary><c>.gltf</c>: the JSON, with its buffer in a <c>.bin</c> file of the same name beside it.</summary>
  Json,
}
