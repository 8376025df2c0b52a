MODULE Partner
  VAR syncident ready;
  PERS tasks both{2} := [["main task"], ["task 2 (partner)"]];
  VAR iodev log;
  VAR num steps := 0;
  PROC main()
    steps := steps + 1;                  ! VISIBLE
    Open "HOME:" \File:="log.txt", log \Write;  ! LOCAL
    Write log, "step";                   ! LOCAL
    WaitSyncTask ready, both;            ! SHARED
    TPReadNum steps, "Steps?";           ! SHARED
  ENDPROC                                ! SHARED
ENDMODULE
