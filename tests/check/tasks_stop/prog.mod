MODULE TasksStopMain
    ! The main task stops once; the second task counts beside it.
    PERS num count := 0;
    VAR num x := 0;
    PROC main()
        x := 1;
        Stop;
        x := 2;
    ENDPROC
ENDMODULE
