MODULE Receiver
    ! Written for the test (issue 28): the receiver answers the robot's phase 1 with 2.
    PERS num phase := 0;

    PROC main()
        WHILE TRUE DO
            WaitUntil phase = 1;
            phase := 2;
        ENDWHILE
    ENDPROC
ENDMODULE
