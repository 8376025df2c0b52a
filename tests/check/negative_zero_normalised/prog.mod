MODULE prog
  ! -x of x = 0 is 0, not -0 (no num holds -0: docs/semantics.md), so ATan2(y, -1) is pi
  ! and the division by zero on line 11 never runs, in 'rapidmc run' and in the check
  ! alike. Before, y held -0 while running and read back as 0 from a checked state (the
  ! TPWrite's step stores it), so run and check disagreed.
  VAR num x := 0;
  VAR num y := 0;
  PROC main()
    y := -x;
    TPWrite "y";
    IF ATan2(y, -1) < 0 x := 1 / 0;
    y := 0 * -1;
    TPWrite "z";
    IF ATan2(y, -1) < 0 x := 1 / 0;
  ENDPROC
ENDMODULE
