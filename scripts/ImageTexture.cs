//////////////////////////////////////////////////
// Image texture: one PNG shipped beside this script (data/uv-grid.png, an 8x8 grid
// with an "F" at its top left) on a picture, a ball, a box and a tiled floor.
// The path is relative: it is found beside the script.
// Parameters: filter={bilinear|nearest}, wrap={repeat|mirror|clamp} (the floor's),
// gamma=<double> (1: the PNG's values used as colours, as a COLOR attribute would be).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "filter={bilinear|nearest}, wrap={repeat|mirror|clamp}, gamma=<double> (default 1)";

Dictionary<string, string> p = Util.ParseKeyValueList(param);
string filter = "bilinear";
Util.TryParse(p, "filter", ref filter);
string wrap = "repeat";
Util.TryParse(p, "wrap", ref wrap);
double gamma = 1.0;
Util.TryParse(p, "gamma", ref gamma);

bool bilinear = filter != "nearest";
TextureWrap floorWrap = wrap == "mirror" ? TextureWrap.MirroredRepeat
                      : wrap == "clamp" ? TextureWrap.Clamp
                      : TextureWrap.Repeat;

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.9, 0.9 }, 0.2, 0.7, 0.25, 32));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.05, 0.06, 0.09 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.6, -6.5),
                                new Vector3d(0.0, -0.2, 1.0),
                                50.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -4.0), 1.0));

// --- NODE DEFINITIONS ----------------------------------------------------

// The picture: a 2x2 rectangle turned to face the camera with its lit front side. GrCis's camera
// shows a plane's front with u running to the left (a mirror image): Fu = -1, OffsetU = 1 turns
// u round again. Clamped, since its texture coordinates are exactly [0,1]^2.
Plane picture = new Plane(-1.0, 1.0, -1.0, 1.0);
picture.SetAttribute(PropertyName.TEXTURE, new ImageTexture("data/uv-grid.png", gamma)
{
  Bilinear = bilinear,
  Fu = -1.0,
  OffsetU = 1.0,
  WrapU = TextureWrap.Clamp,
  WrapV = TextureWrap.Clamp,
});
root.InsertChild(picture, Matrix4d.RotateY(Math.PI) * Matrix4d.Scale(1.3) * Matrix4d.CreateTranslation(0.0, 0.6, 2.5));

// The ball: v runs from the +z pole (0) to the -z pole (1), so turning +z down puts the image's
// bottom at the bottom; the image wraps once around the ball in u.
Sphere ball = new Sphere();
ball.SetAttribute(PropertyName.TEXTURE, new ImageTexture("data/uv-grid.png", gamma) { Bilinear = bilinear });
root.InsertChild(ball, Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.RotateY(-0.6) * Matrix4d.CreateTranslation(-2.0, -0.2, 0.3));

// The box: each face shows the image over its two local coordinates; the texture tints COLOR.
Cube box = new Cube();
box.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.85, 0.6 });
box.SetAttribute(PropertyName.TEXTURE, new ImageTexture("data/uv-grid.png", gamma) { Bilinear = bilinear, Multiply = true });
root.InsertChild(box, Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.RotateY(0.6) * Matrix4d.Scale(1.4) * Matrix4d.CreateTranslation(2.0, -0.5, 0.3));

// The floor: an infinite plane, the image tiled every 4 units and darkened by a grey COLOR;
// v points away from the camera (Fv < 0), so the tiles read upright from here.
Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.55, 0.55, 0.55 });
floor.SetAttribute(PropertyName.TEXTURE, new ImageTexture("data/uv-grid.png", gamma)
{
  Bilinear = bilinear,
  Multiply = true,
  Fu = 0.25,
  Fv = -0.25,
  WrapU = floorWrap,
  WrapV = floorWrap,
});
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.2, 0.0));
