MODULE Rob1
    ! Robot 1 works in the zone it shares with the other robot.  It asks the
    ! PLC task for the zone (req1), waits for the grant (grant1), works in
    ! the zone, gives it back (req1 := FALSE) and waits until the PLC has
    ! taken the grant back before it asks again.
    PERS bool req1 := FALSE;
    PERS bool grant1 := FALSE;
    CONST robtarget pHome := [[600,-400,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pZone := [[900,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WHILE TRUE DO
            req1 := TRUE;
            WaitUntil grant1;
            WorkInZone;
            req1 := FALSE;
            WaitUntil NOT grant1;
        ENDWHILE
    ENDPROC

    PROC WorkInZone()
        MoveJ pZone, v1000, fine, tool0;
        MoveJ pHome, v1000, fine, tool0;
    ENDPROC
ENDMODULE
