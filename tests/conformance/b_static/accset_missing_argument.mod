MODULE MainModule
  ! Tests: AccSet requires Acc and Ramp; one argument is a static argument error.
  PROC main()
    TPWrite "must not run";
    AccSet 50;
  ENDPROC
ENDMODULE
