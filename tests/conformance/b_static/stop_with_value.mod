MODULE MainModule
  ! Tests: Stop takes no required argument; giving one is a static argument error.
  PROC main()
    TPWrite "must not run";
    Stop 5;
  ENDPROC
ENDMODULE
