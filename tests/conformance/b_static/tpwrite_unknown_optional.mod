MODULE MainModule
  ! Tests: an optional argument name TPWrite does not declare is a static argument error.
  PROC main()
    TPWrite "must not run";
    TPWrite "x" \Value:=1;
  ENDPROC
ENDMODULE
