namespace Rendering;

/// <summary>
/// The coordinator of GrCis's demo (its render threads and point cloud). Students' <c>shade</c>
/// overrides copied from GrCis write <c>Master.singleton?.pointCloud?.AddToPointCloud(…)</c>; here
/// <see cref="singleton"/> stays null, so such code compiles and does nothing. The port's point cloud
/// export is the demo's extra views (PLY).
/// </summary>
public class Master
{
  public static Master? singleton;

  public PointCloud? pointCloud;
}
