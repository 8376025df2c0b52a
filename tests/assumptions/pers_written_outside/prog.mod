MODULE WaitsForPlc
    ! bStart and nCommand are written by no task loaded here: on the controller a PC or
    ! another task sets them. Their reads take any value of their domains (issue 28), so
    ! the waits end and no_deadlock holds; each verdict names both and their values.
    ! nRecipe is only added, never compared: it keeps its one value.
    PERS bool bStart := FALSE;
    PERS num nCommand := 0;
    PERS num nDone := 0;
    PERS num nRecipe := 1;

    PROC main()
        WaitUntil bStart;
        WaitUntil nCommand <> 0;
        TEST nCommand
        CASE 1, 2:
            nDone := nDone + nRecipe;
        ENDTEST
    ENDPROC
ENDMODULE
