MODULE Axes
    ! The ROS modules' test for an external axis the robot lacks (9E9: not connected).
    VAR num connected := 0;
    VAR num sent := 0;

    PROC main()
        VAR jointtarget joints;
        VAR robtarget here;
        joints := CJointT();
        IF joints.extax.eax_a <> 9E9 THEN
            connected := 1;
        ENDIF
        here := CRobT(\Tool:=tool0 \WObj:=wobj0);
        IF here.extax.eax_f <> 9E9 THEN
            connected := 2;
        ENDIF
        sent := 1;
    ENDPROC
ENDMODULE
