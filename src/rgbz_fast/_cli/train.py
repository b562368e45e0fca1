"""``rgbz-fast train``: dataset -> filters of the "learned" or "z_guided" reconstruction (.npz)."""

from __future__ import annotations

from pathlib import Path

from . import _common as c

NAME = "train"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "dataset -> filters of the learned reconstruction",
        "Fit the filters of method 'learned' (hashed 7x7 linear filters, see the user guide) "
        "to a folder of images, with the evaluation's protocol (sRGB EOTF, mosaic at "
        "--bit-depth), and write them to --out. Fit on images you do not evaluate on. "
        "With --z-guided, fit those of method 'z_guided' on a folder of registered RGB + NIR "
        "pairs (NNNN_rgb.png + NNNN_nir.png): each pair through the sensor model, noise-free "
        "and noisy (11 bits), on top of the shipped learned filters of the pattern.")
    p.add_argument("--dataset", type=c.path, required=True, metavar="DIR", action="append",
                   help="folder of RGB images to fit on (required; repeat it to fit on several "
                        "folders; keep the images you evaluate on out of them)")
    c.add_pattern(p, "mask1", "RGB-Z pattern: mask1, mask2 or a tile such as ZR/BG (default: "
                              "mask1)")
    c.add_output_file(p, "the .npz file to write")
    c.add_bit_depth(p, 11, "bits of the frames the filters are for")
    p.add_argument("--noise", action="store_true",
                   help="fit on frames of the sensor noise model (default: noise-free mosaics)")
    c.add_linearise(p, "fits on")
    p.add_argument("--encoding", choices=("linear", "srgb", "both"), default=None,
                   help="the frames' encoding: linear (--linearise), srgb (--no-linearise) or "
                        "both, every image twice (the shipped filters) (default: from "
                        "--linearise)")
    p.add_argument("--name", default=None,
                   help="training set name kept in the file (default: the folders' names "
                        "joined by +)")
    c.add_limit(p, "the first N images of each --dataset folder (default: all)")
    p.add_argument("--radius", type=c.positive_int, default=3,
                   help="window radius of the filter taps (3: a 7x7 window)")
    p.add_argument("--hash-radius", type=c.positive_int, default=3,
                   help="window radius of the gradients the hash is computed from")
    p.add_argument("--strength", type=c.positive_int, default=3,
                   help="strength levels of the hash")
    p.add_argument("--coherence", type=c.positive_int, default=3,
                   help="coherence levels of the hash")
    p.add_argument("--spread", type=c.positive_int, default=3,
                   help="channel-spread levels of the hash (1: none)")
    p.add_argument("--ridge", type=c.positive_float, default=None,
                   help="ridge regularisation, relative to the mean diagonal of the normal "
                        "matrix (default: 1e-3; with --z-guided, set by --select)")
    p.add_argument("--prior", type=c.non_negative_float, default=None,
                   help="weight, in training sites, of the common filter in each bucket's fit "
                        "(default: 50; with --z-guided, set by --select)")
    p.add_argument("--z-guided", action="store_true",
                   help="fit the filters of method z_guided (guided by the NIR amplitude of the "
                        "Z pixels) on RGB + NIR pairs; --bit-depth, --noise, --linearise, "
                        "--encoding, --radius, --hash-radius, --strength, --coherence and "
                        "--spread do not apply (refused when they differ from what it uses: "
                        "11 bits, linear, the shipped hash)")
    p.add_argument("--colour-prior", type=c.positive_float, default=None,
                   help="--z-guided: the prior of the colour correction, times --prior "
                        "(default: set by --select)")
    p.add_argument("--select", choices=("cv", "none"), default=None,
                   help="--z-guided: how --ridge, --prior and --colour-prior are set when not "
                        "given: cv, the best of a grid by k-fold cross-validation over the "
                        "pairs (the shipped filters); none, the fixed settings ridge 1e-3, "
                        "prior 50, colour prior 4 (default: cv)")
    p.add_argument("--cv-folds", type=c.positive_int, default=None,
                   help="--z-guided: folds of --select cv, >= 2 (default: 4)")
    c.add_seed(p, None, "noise seed: with --noise, of the first image (the next image takes "
                        "the next seed; default: 0); with --z-guided, of every pair's noisy "
                        "frame (default: 1)")
    c.add_quiet(p, "no progress bar or summary line")
    c.add_limits(p)
    return p


def run(args):
    from ..evaluation import train_filters
    from ..io import folder_dataset

    _check_z_options(args)
    # the pattern first, naming the option (a Bayer tile had been refused as the evaluation's
    # "patterns" after the folder was read)
    c.z_patterns([args.pattern], "--pattern")
    c.output_file(args.out)
    for d in args.dataset:
        if not (c._exists(d, "--dataset") and d.is_dir()):
            raise c.CliError(f"--dataset: {d} is not a folder")
    from ..io import IMAGE_SUFFIXES, RAW_SUFFIXES

    sources = [s for d in args.dataset
               for s in folder_dataset(d, args.limit, **c.limits(args))]
    if sources and all(s.is_raw for s in sources) and not args.z_guided:
        for dest in _SIMULATION:
            flag = c.given_as(args, dest)
            if flag:
                # they had been ignored, and written into the filters' metadata as applied
                raise c.CliError(f"{flag}: applies to the RGB images the fit mosaics; the "
                                 "dataset's raw files are fitted on as they are (their own bit "
                                 "depth, noise and encoding)")
    c.check_outputs([("the filters", args.out)], [Path(s.location) for s in sources],
                    [(d, IMAGE_SUFFIXES | RAW_SUFFIXES) for d in args.dataset])
    name = args.name or "+".join(d.resolve().name for d in args.dataset)
    if args.z_guided:
        filters = train_filters(
            sources, args.pattern, name=name, progress=c.bars(args), z_guided=True,
            seed=1 if args.seed is None else args.seed, ridge=args.ridge, prior=args.prior,
            colour_prior=args.colour_prior,
            select=None if args.select == "none" else "cv",
            cv_folds=4 if args.cv_folds is None else args.cv_folds,
            meta={"command": c.command_line(args)})
        filters.save(args.out)
        if not args.quiet:
            print(f"{filters} -> {args.out} ({filters.meta['n_images']} frames, "
                  f"{filters.meta['n_sites']} sites)")
        return 0
    filters = train_filters(
        sources, args.pattern, bit_depth=args.bit_depth, noise=args.noise,
        linearise=args.linearise, encoding=args.encoding, name=name,
        seed=0 if args.seed is None else args.seed, progress=c.bars(args), radius=args.radius,
        hash_radius=args.hash_radius,
        n_strength=args.strength, n_coherence=args.coherence, n_spread=args.spread,
        ridge=args.ridge, prior=args.prior, meta={"command": c.command_line(args)})
    filters.save(args.out)
    if not args.quiet:
        m = filters.meta
        # frames: an image at both encodings (--encoding both) is two
        print(f"{filters} -> {args.out} ({m['n_images']} frames, {m['n_sites']} sites, "
              f"{m['empty_buckets']} empty buckets)")
    return 0


#: the options that say how the fit's frames are made from RGB images (a raw file's are its own)
_SIMULATION = ("noise", "bit_depth", "linearise", "encoding")
#: options of the learned fit that --z-guided does not take (its frames are the sensor model's,
#: 11-bit, noise-free and noisy, linear; its hash is the shipped learned filters')
_NOT_Z_GUIDED = _SIMULATION + ("radius", "hash_radius", "strength", "coherence", "spread")


def _check_z_options(args):
    """The options of --z-guided alone: refused without it, and --cv-folds with --select cv;
    the learned fit's own options refused with it (they had been accepted and ignored)."""
    if args.z_guided:
        for dest in _NOT_Z_GUIDED:
            # a value equal to what the fit uses (--bit-depth 11, --linearise, --encoding
            # linear, the shipped hash's radii and levels) is what it does: accepted
            uses = "linear" if dest == "encoding" else args.parser.get_default(dest)
            flag = c.given_as(args, dest)
            if flag and getattr(args, dest) != uses:
                raise c.CliError(f"{flag}: does not apply with --z-guided (its frames are the "
                                 "sensor model's, 11-bit, noise-free and noisy, linear, and "
                                 "its hash is that of the shipped learned filters)")
    if not args.z_guided:
        for flag, value in (("--colour-prior", args.colour_prior), ("--select", args.select),
                            ("--cv-folds", args.cv_folds)):
            if value is not None:
                raise c.CliError(f"{flag}: applies with --z-guided only")
        if args.seed is not None and not args.noise:
            # the noisy fit takes it (it had been refused: the command fitted with seed 0 only)
            raise c.CliError("--seed: applies with --noise or --z-guided (a noise-free fit "
                             "draws nothing)")
    if args.encoding in ("linear", "both") and not args.linearise:
        # --no-linearise had been dropped without a word
        raise c.CliError(f"--encoding: {args.encoding} contradicts --no-linearise (the sRGB "
                         "values); give one of them")
    if args.encoding == "srgb" and args.linearise and c.given(args, "linearise"):
        raise c.CliError("--encoding: srgb contradicts --linearise (the linear values); give "
                         "one of them")
    seen = {}
    for d in args.dataset:                 # a folder given twice was trained on twice
        if not c._exists(d, "--dataset"):
            # before resolve(), whose RuntimeError on a loop of links had been a traceback
            raise c.CliError(f"--dataset: {d} does not exist")
        try:
            key = str(d.resolve())
        except (OSError, RuntimeError) as exc:
            raise c.CliError(f"--dataset: {d}: {getattr(exc, 'strerror', None) or exc}") \
                from None
        if key in seen:
            raise c.CliError(f"--dataset: {d} is given twice (as {seen[key]}); name each "
                             "folder once")
        seen[key] = d
    if not args.z_guided and args.hash_radius > args.radius:
        # the library named --hash-radius even when only --radius was given
        if c.given(args, "hash_radius"):
            raise c.CliError(f"--hash-radius: the gradients' window ({args.hash_radius}) may "
                             f"not exceed the filter's (--radius {args.radius})")
        raise c.CliError(f"--radius: {args.radius} is narrower than the default --hash-radius "
                         f"{args.hash_radius} (the gradients' window may not exceed the "
                         f"filter's); give --hash-radius {args.radius} or less")
    if args.noise and not args.linearise and c.given(args, "linearise"):
        raise c.CliError("--no-linearise: the sensor model (--noise) takes linear light; fit "
                         "noisy frames without it")
    if args.cv_folds is not None:
        if args.select == "none":
            raise c.CliError("--cv-folds: applies to --select cv only")
        if args.cv_folds < 2:
            raise c.CliError(f"--cv-folds: expected an integer >= 2, got {args.cv_folds}")
