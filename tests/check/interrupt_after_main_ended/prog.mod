MODULE Main
  ! The main task ends right after it says so; only then does the watcher task order its
  ! interrupt, which it still serves on its own stack.
  PERS bool main_done := FALSE;
  PROC main()
    main_done := TRUE;
  ENDPROC
ENDMODULE
