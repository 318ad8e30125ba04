"""Descriptors shaped like dvpr's synthetic model (docs/synthetic_model.md), for the peer benchmarks.

Not dvpr's generator (dvpr cannot write its descriptors out): a cheap stand-in with the same
shape and the same broad statistics - d = 128, L2-normalised, variance decaying as 1/(j+1) over
dimensions (the PCA-like decay), training drawn from 30 environments each with its own mean,
deployment descriptors varying smoothly with position along the trajectory (random Fourier
features of x, z) plus noise. Timings of k-means and of nearest-neighbour search depend on N, d,
k and the iteration count, which this reproduces; the exact numbers (AUC) are not dvpr's.
"""
import numpy as np

DIM = 128


def _decay(dim):
    return 1.0 / np.sqrt(np.arange(1, dim + 1, dtype=np.float64))


def _normalise(x):
    return (x / np.linalg.norm(x, axis=1, keepdims=True)).astype(np.float32)


def training_diverse(samples=20000, environments=30, dim=DIM, seed=2):
    """samples x dim float32 from `environments` environments (means of std 0.8), spread evenly."""
    rng = np.random.default_rng(seed)
    means = 0.8 * rng.standard_normal((environments, dim))
    env = np.arange(samples) % environments
    x = means[env] + rng.standard_normal((samples, dim)) * np.sqrt(1 + 0.45**2 + 0.25**2)
    return _normalise(x * _decay(dim))


def kitti_positions(path):
    """(N, 2) x, z positions of a KITTI pose file (elements 4 and 12 of each row)."""
    poses = np.loadtxt(path)
    return poses[:, [3, 11]]


def deployment(positions, dim=DIM, features=256, seed=1):
    """One descriptor per frame: a smooth random field of position plus appearance noise."""
    rng = np.random.default_rng(seed)
    scales = np.exp(rng.uniform(np.log(2.0), np.log(25.0), features))
    freq = rng.standard_normal((features, 2)) / scales[:, None]
    phase = rng.uniform(0, 2 * np.pi, features)
    weights = rng.standard_normal((features, dim)) * np.sqrt(2.0 / features)
    field = np.cos(positions @ freq.T + phase) @ weights
    x = 0.8 * rng.standard_normal(dim) + field + 0.25 * rng.standard_normal(field.shape)
    return _normalise(x * _decay(dim))
