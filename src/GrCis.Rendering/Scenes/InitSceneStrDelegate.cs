namespace Rendering;

/// <summary>GrCis's scene builder that reads data files (names): returns what it loaded (e.g. triangles), negative on failure.</summary>
public delegate long InitSceneStrDelegate(IRayScene sc, string[] names);
