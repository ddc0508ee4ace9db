namespace Rendering;

/// <summary>Names of node attributes and of script context keys (the string values are part of the contract).</summary>
public static class PropertyName
{
  // Node attributes.
  /// <summary>Node attribute: the surface colour, a <c>double[]</c> (one value per band, usually RGB in [0, 1]); wins over the material's colour.</summary>
  public const string COLOR = "color";
  /// <summary>Node attribute: an <see cref="ITexture"/> or a list of them (see <see cref="DefaultSceneNode.AddTexture"/>); textures of all ancestors apply too.</summary>
  public const string TEXTURE = "texture";
  /// <summary>Node attribute: the <see cref="IReflectanceModel"/> (default: a <see cref="PhongModel"/>).</summary>
  public const string REFLECTANCE_MODEL = "reflectance";
  /// <summary>Node attribute: the <see cref="IMaterial"/> (default: the reflectance model's default material).</summary>
  public const string MATERIAL = "material";
  /// <summary>Node attribute: a <see cref="RecursionFunction"/> with which the solid shades itself in ray tracing.</summary>
  public const string RECURSION = "recursion";
  /// <summary>Node attribute: any non-null value makes the solid cast no shadow (read on the solid itself, not inherited).</summary>
  public const string NO_SHADOW = "noShadow";

  // Script context keys.
  /// <summary>Script context key: present (true) while the script runs its preprocessing call, on a scratch scene.</summary>
  public const string CTX_PREPROCESSING = "Preprocessing";
  /// <summary>Script context key: the <see cref="IRayScene"/> the script fills.</summary>
  public const string CTX_SCENE = "Scene";
  /// <summary>Script context key: the scene's name (a string).</summary>
  public const string CTX_SCENE_NAME = "SceneName";
  /// <summary>Script context key: the full path of the script file.</summary>
  public const string CTX_SCRIPT_PATH = "ScriptPath";
  /// <summary>Script context key: image width in pixels; a script may set it.</summary>
  public const string CTX_WIDTH = "Width";
  /// <summary>Script context key: image height in pixels; a script may set it.</summary>
  public const string CTX_HEIGHT = "Height";
  /// <summary>Script context key: samples per pixel; a script may set it.</summary>
  public const string CTX_SUPERSAMPLING = "SuperSampling";
  /// <summary>Script context key: the <see cref="IImageFunction"/> the script chooses (e.g. a <see cref="RayTracing"/> object).</summary>
  public const string CTX_ALGORITHM = "Algorithm";
  /// <summary>Script context key: the <see cref="IRenderer"/> the script chooses (e.g. a <see cref="SupersamplingImageSynthesizer"/>).</summary>
  public const string CTX_SYNTHESIZER = "Synth";
  /// <summary>Script context key: help text for the script's parameters (a string).</summary>
  public const string CTX_TOOLTIP = "ToolTip";
  /// <summary>Script context key: start time of the animation in seconds.</summary>
  public const string CTX_START_ANIM = "Start";
  /// <summary>Script context key: end time of the animation in seconds.</summary>
  public const string CTX_END_ANIM = "End";
  /// <summary>Script context key: the time (in seconds) of a still image that the script chooses.</summary>
  public const string CTX_TIME = "Time";
  /// <summary>Script context key: frames per second of the animation.</summary>
  public const string CTX_FPS = "Fps";
}
