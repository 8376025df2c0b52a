MODULE Rob1
  ! Written for the test: robot 1 asks a function whether robot 2 has set the start flag.
  PERS bool start_flag := FALSE;
  PERS string command := "";

  FUNC bool Started()
    RETURN start_flag AND command = "pick";
  ENDFUNC

  PROC main()
    WaitUntil Started();
    TPWrite "picking";
  ENDPROC
ENDMODULE
