MODULE MainModule
  ! Tests: TPWrite \Num takes a num; a string value is a static type error.
  PROC main()
    TPWrite "must not run";
    TPWrite "x" \Num:="5";
  ENDPROC
ENDMODULE
