//////////////////////////////////////////////////
// Mesh vase: a triangle mesh read from a Wavefront OBJ file shipped beside this
// script (data/vase.obj), resolved through context[CTX_SCRIPT_PATH].
// Parameters: smooth (interpolated normals, default on), mat={glazed|glass|matte}.

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "smooth=<bool> (default true), mat={glazed|glass|matte}";

Dictionary<string, string> p = Util.ParseKeyValueList(param);
bool smooth = true;
Util.TryParse(p, "smooth", ref smooth);
string mat = "glazed";
Util.TryParse(p, "mat", ref mat);

// The OBJ file lies in data/ beside the script.
string scriptPath = context.TryGetValue(PropertyName.CTX_SCRIPT_PATH, out object sp) ? sp as string : null;
string dir = scriptPath != null ? System.IO.Path.GetDirectoryName(scriptPath) : ".";
string objFile = System.IO.Path.Combine(dir, "data", "vase.obj");

SceneBrep brep = new SceneBrep();
WavefrontObj obj = new WavefrontObj();
int triangles = obj.ReadBrep(objFile, brep);
brep.ComputeNormals();
context["triangles"] = triangles;

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.8, 0.8, 0.8 }, 0.1, 0.7, 0.3, 32));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.4, -4.5),
                                new Vector3d(0.0, -0.3, 1.0),
                                45.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -3.0), 1.1));

// --- NODE DEFINITIONS ----------------------------------------------------

// The vase (an open surface: the rim is not capped).
TriangleMesh vase = new TriangleMesh(brep);
vase.Smooth = smooth;
vase.ShellMode = false;
PhongMaterial pm;
switch (mat)
{
  case "glass":
    pm = new PhongMaterial(new double[] { 0.05, 0.15, 0.1 }, 0.05, 0.05, 0.1, 128);
    pm.n = 1.5;
    pm.Kt = 0.9;
    break;

  case "matte":
    pm = new PhongMaterial(new double[] { 0.2, 0.4, 0.8 }, 0.15, 0.85, 0.0, 4);
    break;

  default:
    pm = new PhongMaterial(new double[] { 0.2, 0.4, 0.8 }, 0.1, 0.6, 0.5, 96);
    break;
}
vase.SetAttribute(PropertyName.MATERIAL, pm);
root.InsertChild(vase, Matrix4d.Scale(1.1) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

// Infinite plane with checker.
Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.3, 0.0, 0.0 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.6, 0.6, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
