MODULE MainModule
  ! Tests: Pow with a negative base and a non-integer exponent is a run-time error
  ! (documented limitation; error number undocumented).
  PROC main()
    VAR num x;
    TPWrite "before";
    x := Pow(-8, 0.5);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
