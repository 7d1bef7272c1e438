#!/usr/bin/env python3
"""OpenCV's ArUco detector for `skinlab bench track`, and a video decoder for its frames.

Timing (the bench starts this and talks to it over stdin/stdout, so that its rounds alternate
with the Java contenders' in one run):

    aruco_opencv.py --frames DIR --codes FILE --camera fx,fy,cx,cy,k1,k2,p1,p2,k3 --marker-size M [--clock cpu]

reads DIR's *.pgm frames in name order and the dictionary's codes from FILE (first line
"GRID MAX_CORRECTION", then one line per id of GRID*GRID characters, '1' for a white cell, rows
from the printed marker's top: the cells BoofCV prints, so OpenCV reads the same ids), prints one
JSON line {"opencv": VERSION, "frames": N} (or {"error": WHY} when cv2 is missing), then answers
each line on stdin: "round" with a JSON list of per-frame milliseconds, "ids" with a JSON list
of the ids found per frame. One thread (cv2.setNumThreads(1)). Each frame: detectMarkers with
OpenCV's default parameters, then solvePnP (IPPE_SQUARE) per marker, as BoofCV's contenders
estimate each marker's pose. --clock cpu times by the thread's CPU time instead of the wall clock.

Decoding (OpenCV reads H.264 that the desktop's pure-Java decoder does not, e.g. interlaced):

    aruco_opencv.py --decode VIDEO OUTDIR

writes VIDEO's frames as gray PNG files OUTDIR/f00000.png, ...
"""
import argparse
import glob
import json
import os
import sys
import time


def fail(message):
    print(json.dumps({"error": message}), flush=True)
    sys.exit(0)


def decode(cv2, video, out):
    capture = cv2.VideoCapture(video)
    if not capture.isOpened():
        sys.exit(video + ": OpenCV cannot open it as a video")
    os.makedirs(out, exist_ok=True)
    n = 0
    while True:
        ok, frame = capture.read()
        if not ok:
            break
        gray = cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY) if frame.ndim == 3 else frame
        cv2.imwrite(os.path.join(out, "f%05d.png" % n), gray)
        n += 1
    if n == 0:
        sys.exit(video + ": no frames")
    print("%d frames of %dx%d to %s" % (n, gray.shape[1], gray.shape[0], out))


def dictionary(cv2, np, path):
    with open(path) as f:
        lines = [line.strip() for line in f if line.strip()]
    grid, correction = (int(v) for v in lines[0].split())
    codes = []
    for i, line in enumerate(lines[1:]):
        if len(line) != grid * grid or set(line) - {"0", "1"}:
            fail("%s: code %d is not %d bits of 0/1" % (path, i, grid * grid))
        bits = np.array([int(c) for c in line], dtype=np.uint8).reshape(grid, grid)
        codes.append(cv2.aruco.Dictionary.getByteListFromBits(bits))
    return cv2.aruco.Dictionary(np.concatenate(codes, axis=0), grid, correction)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames")
    parser.add_argument("--codes")
    parser.add_argument("--camera")
    parser.add_argument("--marker-size", type=float, default=0.1)
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    parser.add_argument("--decode", nargs=2, metavar=("VIDEO", "OUTDIR"))
    args = parser.parse_args()
    try:
        import cv2
        import numpy as np
    except ImportError as e:
        if args.decode:
            sys.exit("OpenCV for Python is not installed: " + str(e))
        fail("not installed (" + str(e) + ")")
    if args.decode:
        decode(cv2, *args.decode)
        return
    if not hasattr(cv2, "aruco") or not hasattr(cv2.aruco, "ArucoDetector"):
        fail("OpenCV %s has no cv2.aruco.ArucoDetector (need 4.7 or newer)" % cv2.__version__)
    cv2.setNumThreads(1)
    files = sorted(glob.glob(os.path.join(args.frames, "*.pgm")))
    frames = [cv2.imread(f, cv2.IMREAD_GRAYSCALE) for f in files]
    if not frames or any(f is None for f in frames):
        fail(args.frames + ": no readable .pgm frames")
    detector = cv2.aruco.ArucoDetector(dictionary(cv2, np, args.codes), cv2.aruco.DetectorParameters())
    fx, fy, cx, cy, k1, k2, p1, p2, k3 = (float(v) for v in args.camera.split(","))
    camera = np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]], dtype=np.float64)
    lens = np.array([k1, k2, p1, p2, k3], dtype=np.float64)
    h = args.marker_size / 2
    # TL, TR, BR, BL with y up: the corner order IPPE_SQUARE requires.
    square = np.array([[-h, h, 0], [h, h, 0], [h, -h, 0], [-h, -h, 0]], dtype=np.float64)

    def search(frame):
        corners, ids, _ = detector.detectMarkers(frame)
        for c in corners:
            cv2.solvePnP(square, c.reshape(4, 2).astype(np.float64), camera, lens, flags=cv2.SOLVEPNP_IPPE_SQUARE)
        return [] if ids is None else sorted(int(i) for i in ids.ravel())

    now = time.thread_time_ns if args.clock == "cpu" else time.perf_counter_ns
    print(json.dumps({"opencv": cv2.__version__, "frames": len(frames)}), flush=True)
    for line in sys.stdin:
        command = line.strip()
        if command == "round":
            millis = []
            for frame in frames:
                start = now()
                search(frame)
                millis.append((now() - start) * 1e-6)
            print(json.dumps(millis), flush=True)
        elif command == "ids":
            print(json.dumps([search(frame) for frame in frames]), flush=True)
        elif command:
            print(json.dumps({"error": "unknown command " + command}), flush=True)


if __name__ == "__main__":
    main()
