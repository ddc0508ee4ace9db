namespace Broken
{
  public class Oops
  {
    public int Value => missing;
  }
}
