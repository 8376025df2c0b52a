MODULE OutsidePersWait
    ! Issue 28: startRob and stCommand are written by no loaded task (a PLC, another task
    ! or an encrypted module writes them). Their reads take any value of their domains,
    ! like a free input, so neither wait is a deadlock (as WaitDI on a free input is not).
    PERS bool startRob := FALSE;
    PERS num stCommand := 0;
    VAR num done := 0;

    PROC main()
        WaitUntil startRob;
        WaitUntil stCommand <> 0;
        TEST stCommand
        CASE 1:
            done := 1;
        CASE 2:
            done := 2;
        ENDTEST
    ENDPROC
ENDMODULE
