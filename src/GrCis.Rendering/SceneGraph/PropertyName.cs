namespace Rendering;

/// <summary>Names of node attributes and of script context keys (the string values are part of the contract).</summary>
public static class PropertyName
{
  // Node attributes.
  public const string COLOR = "color";
  public const string TEXTURE = "texture";
  public const string REFLECTANCE_MODEL = "reflectance";
  public const string MATERIAL = "material";
  public const string RECURSION = "recursion";
  public const string NO_SHADOW = "noShadow";

  // Script context keys.
  public const string CTX_PREPROCESSING = "Preprocessing";
  public const string CTX_SCENE = "Scene";
  public const string CTX_SCENE_NAME = "SceneName";
  public const string CTX_SCRIPT_PATH = "ScriptPath";
  public const string CTX_WIDTH = "Width";
  public const string CTX_HEIGHT = "Height";
  public const string CTX_SUPERSAMPLING = "SuperSampling";
  public const string CTX_ALGORITHM = "Algorithm";
  public const string CTX_SYNTHESIZER = "Synth";
  public const string CTX_TOOLTIP = "ToolTip";
  public const string CTX_START_ANIM = "Start";
  public const string CTX_END_ANIM = "End";
  public const string CTX_TIME = "Time";
  public const string CTX_FPS = "Fps";
}
