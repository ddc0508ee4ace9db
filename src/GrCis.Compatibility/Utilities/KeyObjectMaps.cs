using System.Collections.Generic;
using System.Linq;

namespace Utilities;

/// <summary>
/// A many-to-many relation between key ids and object ids (GrCis): each key id names a set of object ids.
/// The delegates turn ids into the objects they stand for (a key of type <typeparamref name="TKey"/>, an object of
/// type <typeparamref name="TObject"/>); unset, they answer default.
/// </summary>
public class KeyObjectMaps<TKey, TObject>
{
  /// <summary>The sets: key id → its object ids.</summary>
  protected Dictionary<string, HashSet<string>> sets = new();

  public GetCheckObjectDelegate<TKey> GetKey { protected get; set; }

  public GetCheckObjectDelegate<TKey> CheckKey { protected get; set; }

  public GetCheckObjectDelegate<TObject> GetObject { protected get; set; }

  public GetCheckObjectDelegate<TObject> CheckObject { protected get; set; }

  public KeyObjectMaps(GetCheckObjectDelegate<TKey>? getKey = null, GetCheckObjectDelegate<TKey>? checkKey = null,
                       GetCheckObjectDelegate<TObject>? getObject = null, GetCheckObjectDelegate<TObject>? checkObject = null)
  {
    GetKey = getKey ?? (_ => default!);
    CheckKey = checkKey ?? (_ => default!);
    GetObject = getObject ?? (_ => default!);
    CheckObject = checkObject ?? (_ => default!);
  }

  /// <summary>Every key id (a new list).</summary>
  public List<string> AllKeyIds => new(sets.Keys);

  /// <summary>Every object id of any key, once each (a new list).</summary>
  public List<string> AllObjectIds => sets.Values.SelectMany(s => s).Distinct().ToList();

  /// <summary>Number of key ids.</summary>
  public int Count => sets.Count;

  /// <summary>The object ids of <paramref name="setId"/> (a new list; empty for an unknown or null key).</summary>
  public List<string> ObjectIds(string setId) => new(Set(setId) ?? Enumerable.Empty<string>());

  /// <summary>Number of object ids of <paramref name="setId"/> (0 for an unknown or null key).</summary>
  public int Card(string setId) => Set(setId)?.Count ?? 0;

  /// <summary>Relates <paramref name="objectId"/> to <paramref name="setId"/>; false when either is null or the pair was there.</summary>
  public bool AddObject(string setId, string objectId)
  {
    if (setId == null || objectId == null)
      return false;
    if (!sets.TryGetValue(setId, out HashSet<string>? set))
      sets[setId] = set = new HashSet<string>();
    return set.Add(objectId);
  }

  /// <summary>Relates every id of <paramref name="objectIds"/> to <paramref name="setId"/> (nothing for an empty sequence).</summary>
  public void AddObjects(string setId, IEnumerable<string> objectIds)
  {
    if (setId == null || objectIds == null || !objectIds.Any())
      return;
    if (sets.TryGetValue(setId, out HashSet<string>? set))
      set.UnionWith(objectIds);
    else
      sets[setId] = new HashSet<string>(objectIds);
  }

  /// <summary>The same relation from the objects' side: object id → key ids, with the delegates swapped.</summary>
  public KeyObjectMaps<TObject, TKey> Inverse()
  {
    var inverse = new KeyObjectMaps<TObject, TKey>(GetObject, CheckObject, GetKey, CheckKey);
    foreach (KeyValuePair<string, HashSet<string>> pair in sets)
      foreach (string objectId in pair.Value)
        inverse.AddObject(objectId, pair.Key);
    return inverse;
  }

  /// <summary>True when <paramref name="objectId"/> is related to <paramref name="setId"/>.</summary>
  public bool Contains(string setId, string objectId) => objectId != null && (Set(setId)?.Contains(objectId) ?? false);

  HashSet<string>? Set(string setId) => setId != null && sets.TryGetValue(setId, out HashSet<string>? set) ? set : null;
}
