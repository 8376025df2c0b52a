MODULE Robot
    ! Written for the test (issue 28): a PC writes the command; robot 1 waits for it. The
    ! wait keeps the command it saw, which the logger task then reads.
    PERS string stCmd := "";

    PROC main()
        WaitUntil stCmd <> "";
        TPWrite "command " + stCmd;
    ENDPROC
ENDMODULE
