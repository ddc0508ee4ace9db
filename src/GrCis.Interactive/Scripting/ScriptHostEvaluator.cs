using System;
using System.Collections.Generic;
using GrCis.Scripting;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// Runs scene scripts through the Roslyn <see cref="ScriptHost"/> (compiled once per content).
/// Keeps one context per script and content, so a script's preprocessing step runs once, on its
/// first evaluation, and later renders reuse what it stored, as in GrCis's demo.
/// </summary>
public sealed class ScriptHostEvaluator : IScriptEvaluator, IDisposable
{
  readonly bool ownsHost;
  readonly Dictionary<string, (string Hash, Dictionary<string, object> Context)> batches = new();

  public ScriptHostEvaluator(ScriptHost? host = null)
  {
    ownsHost = host == null;
    Host = host ?? new ScriptHost();
  }

  public ScriptHost Host { get; }

  public void Run(string path, string source, IRayScene scene, string param, Dictionary<string, object?> context)
  {
    ArgumentNullException.ThrowIfNull(context);
    try
    {
      CompiledScript script = Host.CompileSource(source, path);
      Dictionary<string, object> batch;
      bool fresh;
      lock (batches)
      {
        fresh = !batches.TryGetValue(script.Path, out var b) || b.Hash != script.ContentHash;
        if (fresh)
          batches[script.Path] = b = (script.ContentHash, new Dictionary<string, object>());
        batch = b.Context;
      }

      if (fresh)
      {
        // GrCis's preprocessing call: once per script content, on a throw-away scene.
        batch[PropertyName.CTX_PREPROCESSING] = true;
        var scratch = new DefaultRayScene();
        batch[PropertyName.CTX_SCENE] = scratch;
        try
        {
          script.Run(scratch, param, batch);
        }
        finally
        {
          batch.Remove(PropertyName.CTX_PREPROCESSING);
        }
      }

      foreach (KeyValuePair<string, object?> kv in context)
        if (kv.Value != null)
          batch[kv.Key] = kv.Value;
        else
          batch.Remove(kv.Key);
      // At least two entries, so the host does not preprocess again.
      ScriptScene run = Host.Run(script, param, batch, scene);
      foreach (KeyValuePair<string, object> kv in batch)
        context[kv.Key] = kv.Value;
      // The host fills the animation range GrCis's way before the run; a range the script left alone is not its choice.
      if (run.Start == null) context.Remove(PropertyName.CTX_START_ANIM);
      if (run.End == null) context.Remove(PropertyName.CTX_END_ANIM);
      if (run.Fps == null) context.Remove(PropertyName.CTX_FPS);
    }
    catch (ScriptCompilationException ex)
    {
      throw new SceneEvaluationException(ex.Message, ex);
    }
    catch (ScriptRuntimeException ex)
    {
      throw new SceneEvaluationException(ex.Message, ex);
    }
  }

  public void Dispose()
  {
    if (ownsHost)
      Host.Dispose();
  }
}
