//////////////////////////////////////////////////
// A GrCis scene script. Render it with
//   grcis render Scene.cs -o scene.png [--param "radius=1.2"] [--size 800x600 --spp 16]
// or open this folder in the studio: grcis studio .
// Your IDE completes the GrCis API and marks errors as you type; `dotnet build` here checks the script.
//
// Globals: scene (the scene to fill), param (the --param text), context (values shared with grcis,
// keys PropertyName.CTX_*). Statements first; methods may go anywhere, classes of your own at the end.

context[PropertyName.CTX_TOOLTIP] = "radius=<double> (of the ball, default 1)";

// Parameters, read strictly: a wrong value is reported instead of ignored.
var p = new GrCis.Scripting.ScriptParameters(param);
double radius = p.GetDouble("radius", 1.0);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 16));
scene.Intersectable = root;

// Background colour.
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0),
                                new Vector3d(0.0, -0.18, 1.0),
                                50.0);

// Light sources.
scene.Sources = new LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 3.0, -3.0), 1.0));

// A ball standing on the floor (inherits the root material).
Sphere ball = new Sphere();
root.InsertChild(ball, Matrix4d.Scale(radius) * Matrix4d.CreateTranslation(0.0, radius - 1.0, 0.0));

// Infinite plane with a checker texture.
Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.5, 0.0, 0.0 });
floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
