namespace Rendering;

/// <summary>Fills a ray scene (geometry, camera, lights, background).</summary>
public delegate void InitSceneDelegate(IRayScene sc);
