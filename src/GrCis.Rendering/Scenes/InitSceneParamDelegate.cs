namespace Rendering;

/// <summary>Fills a ray scene using a user-supplied parameter string (<c>key=value, key2</c> pairs).</summary>
public delegate void InitSceneParamDelegate(IRayScene sc, string param);
