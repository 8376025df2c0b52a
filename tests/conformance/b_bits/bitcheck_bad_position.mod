MODULE MainModule
  ! Tests: BitCheck with a bit position outside 1..8 is a recoverable run-time error.
  PROC main()
    VAR bool b;
    b := BitCheck(1, 9);
    TPWrite "not reached";
  ERROR
    TPWrite "error for position 9";
  ENDPROC
ENDMODULE
