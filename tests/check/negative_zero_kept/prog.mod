MODULE prog
  ! -x of x = 0 is -0 (single precision keeps the sign), and ATan2(-0, -1) is -pi:
  ! 'rapidmc run' stops at the division by zero on line 11. The checker stores y as 0
  ! (an equal value met before) in the state between the two lines (TPWrite's) and its
  ! ATan2 gives +pi: no_runtime_error HOLDS.
  VAR num x := 0;
  VAR num y := 0;
  PROC main()
    y := -x;
    TPWrite "y";
    IF ATan2(y, -1) < 0 x := 1 / 0;
  ENDPROC
ENDMODULE
