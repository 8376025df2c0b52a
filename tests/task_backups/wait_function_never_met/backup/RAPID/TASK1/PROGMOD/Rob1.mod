MODULE Rob1
  ! Written for the test: robot 1 waits, through a function, for a command robot 2 never
  ! gives (robot 2 sends "place", the function asks for "pick").
  PERS bool start_flag := FALSE;
  PERS string command := "";

  FUNC bool PickAsked()
    RETURN start_flag AND command = "pick";
  ENDFUNC

  PROC main()
    WaitUntil PickAsked();
    TPWrite "picking";
  ENDPROC
ENDMODULE
