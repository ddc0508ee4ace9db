// Two mistakes a student makes.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
scene.Intersectable = root;

double radius = 2.0
scene.Camera = new NoSuchCamera(radius);
