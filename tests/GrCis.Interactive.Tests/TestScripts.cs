using System.Globalization;

namespace GrCis.Interactive.Tests;

/// <summary>Scene scripts in the GrCis dialect that need no solids: a camera and a background colour.</summary>
internal static class TestScripts
{
  public static string Background(double red, int width = 40, int height = 30) => string.Create(CultureInfo.InvariantCulture, $$"""
    // Test scene: plain background, size override and a tooltip.
    double g = 0.5;
    Util.TryParse(Util.ParseKeyValueList(param), "g", ref g);
    scene.BackgroundColor = new double[] { {{red}}, g, 0.75 };
    scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60.0);
    scene.Intersectable = new CSGInnerNode(SetOperation.Union);
    scene.Sources = new LinkedList<ILightSource>();
    context[PropertyName.CTX_WIDTH] = {{width}};
    context[PropertyName.CTX_HEIGHT] = {{height}};
    context[PropertyName.CTX_START_ANIM] = 0.0;
    context[PropertyName.CTX_END_ANIM] = 2.0;
    context[PropertyName.CTX_TOOLTIP] = "g = green (0 to 1)";
    """);
}
