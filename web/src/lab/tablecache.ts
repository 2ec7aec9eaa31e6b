// The browser's η-table cache: IndexedDB database
// `steering-lab`, store `tables`, one record per parameter key (the core's
// `tableJob(params).key`, the same hash as the native cache's file names).
// A record is used only after the core has loaded it and recomputed the
// same key from its header (`tableKeyOf`), so a stale or corrupt record is
// rebuilt, never used. Every failure (private mode, quota) is a miss.

const DB = "steering-lab";
const STORE = "tables";

let connection: Promise<IDBDatabase> | null = null;

/** The database, opened once per page and kept open: opening took most of
 *  a cached reload (tens of ms, more on a busy host), so the page starts
 *  it early (`openTableCache`), beside loading the core. */
function open(): Promise<IDBDatabase> {
  connection ??= new Promise<IDBDatabase>((resolve, reject) => {
    const req = indexedDB.open(DB, 1);
    req.onupgradeneeded = () => {
      if (!req.result.objectStoreNames.contains(STORE)) req.result.createObjectStore(STORE);
    };
    req.onsuccess = () => {
      const db = req.result;
      // Another tab upgrading or deleting the database: let it, reopen next time.
      db.onversionchange = () => {
        db.close();
        connection = null;
      };
      db.onclose = () => {
        connection = null;
      };
      resolve(db);
    };
    req.onerror = () => {
      connection = null;
      reject(req.error ?? new Error("indexedDB.open failed"));
    };
  });
  return connection;
}

/** Starts opening the cache (failures show later as misses). */
export function openTableCache(): void {
  open().catch(() => {});
}

function request<T>(mode: IDBTransactionMode, f: (s: IDBObjectStore) => IDBRequest): Promise<T | undefined> {
  return open().then(
    (db) =>
      new Promise<T | undefined>((resolve) => {
        try {
          const tx = db.transaction(STORE, mode);
          const req = f(tx.objectStore(STORE));
          // A read resolves with its request, a write once committed.
          if (mode === "readonly") req.onsuccess = () => resolve(req.result as T | undefined);
          tx.oncomplete = () => resolve(req.result as T | undefined);
          tx.onerror = tx.onabort = () => resolve(undefined);
        } catch {
          resolve(undefined);
        }
      }),
  );
}

/** The bytes cached under `key`, or null. */
export async function cacheGet(key: string): Promise<Uint8Array | null> {
  try {
    const v = await request<ArrayBuffer>("readonly", (s) => s.get(key));
    return v instanceof ArrayBuffer ? new Uint8Array(v) : null;
  } catch {
    return null;
  }
}

/** Stores `bytes` under `key` (failures ignored: the next visit rebuilds). */
export async function cachePut(key: string, bytes: Uint8Array): Promise<void> {
  try {
    const copy = bytes.slice().buffer;
    await request("readwrite", (s) => s.put(copy, key));
  } catch {
    /* a miss next time */
  }
}

/** The keys in the cache (tests). */
export async function cacheKeys(): Promise<string[]> {
  try {
    const v = await request<IDBValidKey[]>("readonly", (s) => s.getAllKeys());
    return (v ?? []).map(String);
  } catch {
    return [];
  }
}
