MODULE Rob2
    ! Robot 2 works in the zone it shares with the other robot.  It asks the
    ! PLC task for the zone (req2), waits for the grant (grant2), works in
    ! the zone, gives it back (req2 := FALSE) and waits until the PLC has
    ! taken the grant back before it asks again.
    PERS bool req2 := FALSE;
    PERS bool grant2 := FALSE;
    CONST robtarget pHome := [[600,400,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pZone := [[900,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WHILE TRUE DO
            req2 := TRUE;
            WaitUntil grant2;
            WorkInZone;
            req2 := FALSE;
            WaitUntil NOT grant2;
        ENDWHILE
    ENDPROC

    PROC WorkInZone()
        MoveJ pZone, v1000, fine, tool0;
        MoveJ pHome, v1000, fine, tool0;
    ENDPROC
ENDMODULE
