//////////////////////////////////////////////////
// Textured torus: a texture class declared in the script (after its use) winds
// spiral stripes around a torus and shades them along the tube.
// Parameters: stripes = number of stripes, turns = how many times they wind round.

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "stripes=<int> (default 12), turns=<double> (default 3)";

Dictionary<string, string> p = Util.ParseKeyValueList(param);
int stripes = 12;
Util.TryParse(p, "stripes", ref stripes);
double turns = 3.0;
Util.TryParse(p, "turns", ref turns);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.9, 0.9 }, 0.15, 0.65, 0.35, 48));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.05, 0.05, 0.1 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 2.0, -6.0),
                                new Vector3d(0.0, -0.35, 1.0),
                                50.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -3.0), 1.2));

// --- NODE DEFINITIONS ----------------------------------------------------

// The torus (axis = local z) laid flat and tilted towards the camera.
Torus t = new Torus(1.5, 0.6);
t.SetAttribute(PropertyName.COLOR, new double[] { 0.9, 0.3, 0.1 });
t.SetAttribute(PropertyName.TEXTURE, new SpiralStripes(stripes, turns, new double[] { 1.0, 0.9, 0.3 }));
root.InsertChild(t, Matrix4d.RotateX(-MathHelper.PiOver2 + 0.35) * Matrix4d.CreateTranslation(0.0, 0.0, 0.5));

// Infinite plane with checker.
Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.1, 0.2, 0.3 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.7, 0.7, new double[] { 0.8, 0.8, 0.8 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

/// <summary>
/// Spiral stripes in texture space: stripe k covers (u * turns + v) * count in [k, k+1);
/// odd stripes take Color2; all colours are darkened towards the inner side of the tube.
/// </summary>
class SpiralStripes : ITexture
{
  public int Count;
  public double Turns;
  public double[] Color2;

  public SpiralStripes(int count, double turns, double[] color2)
  {
    Count = count;
    Turns = turns;
    Color2 = Util.ColorClone(color2);
  }

  public long Apply(Intersection inter)
  {
    double u = inter.TextureCoord.X;
    double v = inter.TextureCoord.Y;
    long k = (long)Math.Floor((u * Turns + v) * Count);
    double[] c = (k & 1L) != 0L ? Util.ColorClone(Color2) : Util.ColorClone(inter.SurfaceColor);
    double shade = 0.6 + 0.4 * Math.Abs(Math.Cos(Math.PI * v));
    for (int i = 0; i < c.Length; i++)
      c[i] *= shade;
    inter.SurfaceColor = c;
    inter.textureApplied = true;
    return (long)MathSupport.RandomStatic.numericRecipes((ulong)(k & 0xffff));
  }
}
