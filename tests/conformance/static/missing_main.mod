MODULE missing_main
  ! Tests: a program without the entry procedure main is a static error
  ! (RMC211).
  PROC start()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
