MODULE WaitMaxTimeFlag
    ! With \TimeFlag a timeout sets the flag and goes on: no error.
    VAR bool late := FALSE;
    VAR bool ready := FALSE;

    PROC main()
        WaitUntil DInput(di_ready) = 1 \MaxTime:=2 \TimeFlag:=late;
        ready := NOT late;
    ENDPROC
ENDMODULE
