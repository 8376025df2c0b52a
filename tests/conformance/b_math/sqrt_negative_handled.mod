MODULE MainModule
  ! Tests: the run-time error of Sqrt(-4) is recoverable: it reaches the ERROR handler.
  PROC main()
    VAR num x;
    x := Sqrt(-4);
    TPWrite "not reached";
  ERROR
    TPWrite "error in Sqrt";
  ENDPROC
ENDMODULE
