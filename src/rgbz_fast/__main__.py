from rgbz_fast.cli import main

raise SystemExit(main())
